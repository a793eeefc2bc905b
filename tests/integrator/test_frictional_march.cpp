// Friction in the linear march (integrator/elastodynamic_march.hpp): a linear elastic disc
// dropped obliquely onto the rigid plane x2 = 0 with Coulomb friction, the step condensed onto
// the normal displacements and the slips of its contact nodes. For every strategy:
//  - the balance of scene 8b, E + interface - friction work - wall work = E0 (Prop. 8.1 with the
//    linear midpoint rule, exact up to the Newton tolerance eps = 1e-10 of the driver's test
//    (iv)), to 1e-9 of E0 at every step;
//  - the friction work of every step <= 0 (dissipative), < 0 on every step with a slipping
//    node, and the friction did dissipate;
//  - the momentum balance (ALGORITHMS.md 4.8 check 6): the change of M v over a step is k times
//    the contact forces (-sum T, sum N) on this plane, which fails if the tangential forces
//    entered the step with a wrong sign or factor; and the Coulomb cone |T_i| <= mu N_i.
// Friction with a vanishing coefficient gives the frictionless march's states: the slips among
// the condensed unknowns change nothing when they carry no force.
#include "assembly/dirichlet.hpp"
#include "contact/contact_elements.hpp"
#include "contact/obstacle.hpp"
#include "integrator/contact_strategy.hpp"
#include "integrator/elastodynamic_march.hpp"
#include "mesh/generators.hpp"
#include "stages/march_inputs.hpp"
#include "test_bodies.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace sig {
namespace {

constexpr double kRadius = 1.0, kGap = 0.02, k = 0.005;
const Eigen::Vector2d kThrow(1.0, -2.0); // sliding to +x1 as it lands at t = 0.01
constexpr double kMu = 0.3;
constexpr double kAllowed = 0.002; // ipm's g, the asperities' depth of mu1 / mu2

/// A Hooke disc (E = 100, rho = 1) of radius 1 with 32 segments, kGap above the plane; its bottom
/// quarter (ref 3) the contact boundary.
struct Disc {
  Mesh mesh = disc({0.0, kRadius + kGap}, kRadius, 32);
  LinearSystem system = test::free_body_system(mesh, test::unit_material(100.0));
  ReducedSystem reduced = reduce(system);
  ContactElements elements;

  explicit Disc(const ContactLaw& law) {
    elements = build_contact_elements(mesh, 3, HalfPlane({0, 0}, {0, 1}), law);
  }
  DynamicState thrown() const {
    Eigen::VectorXd v(system.num_dofs());
    for (int i = 0; i < mesh.num_nodes(); ++i)
      v.segment<2>(2 * i) = kThrow;
    return {0.0, Eigen::VectorXd::Zero(reduced.num_free()), reduced.restrict(v)};
  }
};

ContactLaw law_of(FrictionLaw friction, double mu, double depth) {
  ContactLaw law;
  law.depth = depth;
  law.friction = friction;
  law.mu = mu;
  return law;
}

struct Drop {
  MarchHistory history;
  std::vector<DynamicState> states; ///< every step's, from step 0
  Eigen::SparseMatrix<double> M;
};

Drop drop(const std::string& strategy, const ContactLaw& law, int steps = 80) {
  const Disc disc(law);
  ContactStrategyParameters p;
  p.r = 1e4;     // the foundation per unit area: 100 E per unit length
  p.gamma = 1e4; // PDAS's parameter, of the order of a node's stiffness in the step
  p.eps = 1e-10;
  const auto scheme = make_time_scheme(
      "midpoint", reduced_elastodynamics(disc.reduced, disc.system.M), k, "cholmod");
  const ContactBoundary boundary = contact_boundary(disc.elements, disc.mesh, disc.reduced);
  Drop d;
  d.M = scheme->problem().M;
  d.states.push_back(disc.thrown());
  d.history = march_with_contact(
      *scheme, boundary, *make_contact_strategy(strategy, p), disc.thrown(), steps, 0,
      [&d](const StepRecord&, const DynamicState& state) { d.states.push_back(state); });
  return d;
}

/// sum over the nodes of the components (x, y) of a vector on the free dofs (none is held here).
Eigen::Vector2d resultant(const Eigen::VectorXd& f) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (Eigen::Index i = 0; i < f.size(); i += 2)
    sum += f.segment<2>(i);
  return sum;
}

class ObliqueDrop : public ::testing::TestWithParam<std::tuple<const char*, FrictionLaw, double>> {
};

TEST_P(ObliqueDrop, BalancesEnergyAndMomentumAndFrictionDissipates) {
  const auto [strategy, friction, depth] = GetParam();
  const Drop d = drop(strategy, law_of(friction, kMu, depth));
  ASSERT_TRUE(d.history.converged) << strategy << ": " << d.history.failure;
  const std::vector<StepRecord>& steps = d.history.steps;
  const double e0 = steps[0].energy.total;
  const double most = friction == FrictionLaw::mu2 ? 2 * kMu : kMu; // max mu
  const double momentum = resultant(d.M * d.states[0].v).norm();
  int contact_steps = 0, slipping_steps = 0;
  double worst_balance = 0;
  for (std::size_t n = 1; n < steps.size(); ++n) {
    const EnergyRecord& e = steps[n].energy;
    const EnergyRecord& before = steps[n - 1].energy;
    const ContactRecord& c = steps[n].contact;
    const double balance = e.total + e.interface - e.friction_work - e.wall_work;
    worst_balance = std::max(worst_balance, std::abs(balance - e0));
    EXPECT_NEAR(balance, e0, 1e-9 * e0) << strategy << " step " << n;

    // The friction of the step: -sum T slip <= 0 (a sticking node's slip is round-off), < 0
    // where a loaded node slips.
    const double friction_work = e.friction_work - before.friction_work;
    EXPECT_LE(friction_work, 1e-15 * e0) << strategy << " step " << n;
    bool slipping = false;
    for (Eigen::Index i = 0; i < c.normal_force.size(); ++i) {
      EXPECT_LE(std::abs(c.tangential_force[i]), most * c.normal_force[i] * (1 + 1e-9) + 1e-12)
          << strategy << " step " << n << " node " << i; // the cone
      const auto status = c.friction_status[static_cast<std::size_t>(i)];
      slipping = slipping || (c.normal_force[i] > 0 && (status == FrictionStatus::slip_forward ||
                                                        status == FrictionStatus::slip_backward));
    }
    if (slipping) {
      EXPECT_LT(friction_work, 0.0) << strategy << " step " << n;
      ++slipping_steps;
    }
    contact_steps += e.active_nodes > 0 ? 1 : 0;

    // Check 6: the elastic forces of a step sum to zero, so M (v_n - v_{n-1}) sums to k times
    // the contact forces' resultant (-sum T, sum N) on this plane (t = (1, 0), n = (0, 1)).
    // Rounding of v = (2 / k)(u_n - u_{n-1}) - v_{n-1}: 1e-14 of the momentum.
    const Eigen::Vector2d change = resultant(d.M * (d.states[n].v - d.states[n - 1].v));
    const double scale =
        1e-9 * k * (std::abs(e.normal_force) + std::abs(e.tangential_force)) + 1e-14 * momentum;
    EXPECT_NEAR(change.x(), -k * e.tangential_force, scale) << strategy << " step " << n;
    EXPECT_NEAR(change.y(), k * e.normal_force, scale) << strategy << " step " << n;
  }
  EXPECT_GT(contact_steps, 5) << strategy; // it did land
  EXPECT_GT(slipping_steps, 2) << strategy;
  EXPECT_LT(steps.back().energy.friction_work, -1e-3 * e0) << strategy; // friction dissipated
  RecordProperty("balance_error_over_e0", std::to_string(worst_balance / e0));
  std::printf("%s %s: max |E + interface - friction work - wall work - E0| / E0 = %.3g, friction "
              "work %.6g (E0 %.6g), %d contact steps, %d slipping\n",
              strategy, to_string(friction).c_str(), worst_balance / e0,
              steps.back().energy.friction_work, e0, contact_steps, slipping_steps);
}

INSTANTIATE_TEST_SUITE_P(LinearDisc, ObliqueDrop,
                         ::testing::Values(std::make_tuple("signorini", FrictionLaw::coulomb, 0.0),
                                           std::make_tuple("compliance", FrictionLaw::coulomb, 0.0),
                                           std::make_tuple("specific-penalty", FrictionLaw::coulomb,
                                                           0.0),
                                           std::make_tuple("two-step", FrictionLaw::coulomb, 0.0),
                                           std::make_tuple("ipm", FrictionLaw::coulomb, kAllowed),
                                           // scene 8b's laws of the penetration, with IPM as there
                                           std::make_tuple("ipm", FrictionLaw::mu1, kAllowed),
                                           std::make_tuple("ipm", FrictionLaw::mu2, kAllowed)));

// The slips among the condensed unknowns with a zero bound: the frictionless march, state by
// state, to round-off.
TEST(ObliqueDropWithoutFriction, ZeroCoefficientIsTheFrictionlessMarch) {
  for (const char* strategy : {"signorini", "specific-penalty"}) {
    const Drop frictionless = drop(strategy, law_of(FrictionLaw::none, 0, 0), 40);
    const Drop zero = drop(strategy, law_of(FrictionLaw::coulomb, 0, 0), 40);
    ASSERT_TRUE(frictionless.history.converged && zero.history.converged) << strategy;
    ASSERT_EQ(frictionless.states.size(), zero.states.size());
    for (std::size_t n = 0; n < zero.states.size(); ++n) {
      const DynamicState &a = frictionless.states[n], &b = zero.states[n];
      EXPECT_LT((a.u - b.u).norm(), 1e-12 * (1 + a.u.norm())) << strategy << " step " << n;
      EXPECT_LT((a.v - b.v).norm(), 1e-10 * a.v.norm()) << strategy << " step " << n;
    }
    EXPECT_NEAR(zero.history.steps.back().energy.friction_work, 0.0,
                1e-15 * zero.history.steps[0].energy.total)
        << strategy;
    EXPECT_GT(zero.history.steps.back().energy.active_nodes +
                  zero.history.steps[20].energy.active_nodes,
              0)
        << strategy; // contact happened within the compared steps
  }
}

} // namespace
} // namespace sig
