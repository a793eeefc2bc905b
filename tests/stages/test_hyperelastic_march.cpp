// Hyperelastic dynamics (stages/finite_strain_march.hpp) on a small Ciarlet-Geymonat ring:
// free flight a rigid translation, exact and free of Newton iterations; a spinning and flying
// ring keeping energy and angular momentum with Gonzalez's stress and drifting in energy with the
// plain midpoint stress; the momentum balance of ALGORITHMS.md 4.8 check 6 through an impact,
// with the consistent mass and with the EMM; the specific penalty conserving E + the
// foundation's energy; IPM's penetration <= g; friction only dissipating, each term of the
// balance with its sign.
#include "assembly/pattern.hpp"
#include "assembly/system.hpp"
#include "contact/contact_elements.hpp"
#include "contact/obstacle.hpp"
#include "integrator/contact_strategy.hpp"
#include "integrator/emm.hpp"
#include "material/ciarlet_geymonat.hpp"
#include "material/mili.hpp"
#include "mesh/generators.hpp"
#include "mesh/mesh.hpp"
#include "stages/finite_strain_march.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <optional>
#include <string>

namespace sig {
namespace {

constexpr double kRho = 1000;

/// The thesis's ring material and density, a ring of radii 9 and 10 (as Scene 8b) with 32 nodes
/// around and 3 through the thickness, centred at `centre`; the whole outer circle is Gamma3.
struct Ring {
  Mesh mesh;
  MaterialTable materials;
  Eigen::SparseMatrix<double> mass;
  std::optional<ContactElements> contact;
  std::unique_ptr<Obstacle> plane;

  Eigen::Vector2d centre;

  explicit Ring(const Eigen::Vector2d& c) : centre(c) {
    RingOptions options;
    options.layers = 3;
    options.gamma1_above = 1e9;
    options.gamma3_below = 1e9;
    mesh = ring(centre, 9.0, 10.0, 32, options);
    SubdomainMaterial m;
    m.hyperelastic = std::make_shared<CiarletGeymonat>(0.5e6, 0.5e4, 0.35e6);
    m.hooke = m.hyperelastic->linearized();
    m.density = kRho;
    materials.entries = {m};
    mass = assemble_mass(mesh, materials, SparsityPattern(mesh));
  }

  /// Contact with the plane x2 = 0 on Gamma3 with `law`.
  void with_contact(const ContactLaw& law) {
    plane = std::make_unique<HalfPlane>(Eigen::Vector2d(0, 0), Eigen::Vector2d(0, 1));
    contact = build_contact_elements(mesh, 3, *plane, law);
  }

  /// The EMM (integrator/emm.hpp) instead of the consistent mass: Gamma3's nodes without inertia.
  void with_emm() {
    std::vector<int> gamma3;
    for (int i = 0; i < mesh.num_nodes(); ++i)
      if (std::abs((mesh.nodes[i] - centre).norm() - 10.0) < 1e-9) gamma3.push_back(i);
    ASSERT_EQ(gamma3.size(), 32u); // the outer circle's nodes
    mass = equivalent_mass_matrix(mass, node_positions(mesh), gamma3);
  }

  FiniteStrainProblem problem(double k, AlgorithmicStress stress) const {
    FiniteStrainProblem p;
    p.mesh = &mesh;
    p.materials = &materials;
    p.dirichlet_values = Eigen::VectorXd(0);
    p.contact = contact ? &*contact : nullptr;
    p.obstacle = plane.get();
    p.mass = &mass;
    p.time_step = k;
    p.stress = stress;
    return p;
  }

  /// v + omega e3 x (X - c) at every node, u = 0.
  DynamicState thrown(const Eigen::Vector2d& v, double omega, const Eigen::Vector2d& c) const {
    DynamicState s{0.0, Eigen::VectorXd::Zero(2 * mesh.num_nodes()),
                   Eigen::VectorXd(2 * mesh.num_nodes())};
    for (int i = 0; i < mesh.num_nodes(); ++i) {
      const Eigen::Vector2d r = mesh.nodes[i] - c;
      s.v.segment<2>(2 * i) = v + omega * Eigen::Vector2d(-r.y(), r.x());
    }
    return s;
  }

  /// sum_a x_a x (M v)_a, x = X + u: the angular momentum about the origin.
  double angular_momentum(const DynamicState& s) const {
    const Eigen::VectorXd p = mass * s.v;
    double L = 0;
    for (int i = 0; i < mesh.num_nodes(); ++i) {
      const Eigen::Vector2d x = mesh.nodes[i] + s.u.segment<2>(2 * i);
      L += x.x() * p[2 * i + 1] - x.y() * p[2 * i];
    }
    return L;
  }
};

HyperelasticMarchOptions options() {
  HyperelasticMarchOptions o;
  o.backend = "umfpack";
  o.eps = 1e-10;
  return o;
}

// Steps 1-2699 of Scene 8b in small: a rigid translation is the predictor of every step, so the
// states are exact (u_n = n k v to rounding), no Newton iteration is spent and the energy stays.
TEST(HyperelasticMarch, FreeFlightIsExactAndCostsNoIteration) {
  const Ring ring({100, 100});
  const Eigen::Vector2d v(10, -10);
  const double k = 1.0 / 300;
  std::vector<DynamicState> states;
  const MarchHistory h = march_hyperelastic(
      ring.problem(k, AlgorithmicStress::gonzalez), nullptr, options(), ring.thrown(v, 0, {0, 0}),
      300, 0, [&](const StepRecord&, const DynamicState& s) { states.push_back(s); });
  ASSERT_TRUE(h.converged) << h.failure;
  const double e0 = h.steps[0].energy.total;
  EXPECT_NEAR(e0, 0.5 * kRho * ring.mass.sum() / kRho * v.squaredNorm() / 2, 1e-9 * e0);
  for (std::size_t n = 0; n < states.size(); ++n) {
    for (int i = 0; i < ring.mesh.num_nodes(); ++i) {
      EXPECT_LT((states[n].u.segment<2>(2 * i) - (n + 1.0) * k * v).norm(), 1e-12 * (n + 1));
      EXPECT_LT((states[n].v.segment<2>(2 * i) - v).norm(), 1e-12);
    }
    EXPECT_EQ(h.steps[n + 1].iterations, 0);
    EXPECT_NEAR(h.steps[n + 1].energy.total, e0, 1e-13 * e0);
  }
}

struct SpinRun {
  MarchHistory history;
  std::vector<double> angular_momentum;
};

SpinRun spin(AlgorithmicStress stress, double k, int steps, bool emm = false) {
  Ring ring({0, 0});
  if (emm) ring.with_emm();
  SpinRun r;
  const DynamicState start = ring.thrown({3, -1}, 4.0, {0, 0}); // 40 m/s at the rim
  r.angular_momentum.push_back(ring.angular_momentum(start));
  r.history = march_hyperelastic(ring.problem(k, stress), nullptr, options(), start, steps, 0,
                                 [&](const StepRecord&, const DynamicState& s) {
                                   r.angular_momentum.push_back(ring.angular_momentum(s));
                                 });
  return r;
}

// A spinning and flying ring stretches and vibrates: Gonzalez's stress keeps its energy and its
// angular momentum to the Newton tolerance at a step as large as a tenth of a turn; the plain
// midpoint stress keeps the angular momentum too (Pi F_m^T symmetric) but not the energy.
TEST(HyperelasticMarch, SpinningRingKeepsEnergyAndAngularMomentumWithGonzalez) {
  const double k = 0.15; // 4 rad/s: a tenth of a turn per step
  const SpinRun g = spin(AlgorithmicStress::gonzalez, k, 60);
  const SpinRun m = spin(AlgorithmicStress::midpoint, k, 60);
  ASSERT_TRUE(g.history.converged) << g.history.failure;
  ASSERT_TRUE(m.history.converged) << m.history.failure;
  const double e0 = g.history.steps[0].energy.total, L0 = g.angular_momentum[0];
  double drift_g = 0, drift_m = 0, spin_g = 0, spin_m = 0, strain = 0;
  for (std::size_t n = 0; n < g.history.steps.size(); ++n) {
    drift_g = std::max(drift_g, std::abs(g.history.steps[n].energy.total - e0));
    drift_m = std::max(drift_m, std::abs(m.history.steps[n].energy.total - e0));
    spin_g = std::max(spin_g, std::abs(g.angular_momentum[n] - L0));
    spin_m = std::max(spin_m, std::abs(m.angular_momentum[n] - L0));
    strain = std::max(strain, g.history.steps[n].energy.elastic);
  }
  EXPECT_GT(strain, 1e-3 * e0); // it did deform: the test is not a rigid rotation
  EXPECT_LT(drift_g, 1e-9 * e0);
  EXPECT_LT(spin_g, 1e-9 * std::abs(L0));
  EXPECT_LT(spin_m, 1e-9 * std::abs(L0));
  EXPECT_GT(drift_m, 1e3 * drift_g);
  EXPECT_GT(drift_m, 1e-6 * e0);
}

// The EMM leaves the outer circle without inertia (integrator/emm.hpp; on this 3-layer ring it
// keeps the mass and the centre only, with a warning: the moments of inertia too would make it
// indefinite): the spinning ring still keeps its energy, and its angular momentum since
// Me = me (x) I_2 with me symmetric, to the Newton tolerance.
TEST(HyperelasticMarch, SpinningRingUnderTheEmmKeepsEnergyAndAngularMomentum) {
  const SpinRun r = spin(AlgorithmicStress::gonzalez, 0.15, 60, true);
  ASSERT_TRUE(r.history.converged) << r.history.failure;
  const double e0 = r.history.steps[0].energy.total, L0 = r.angular_momentum[0];
  double drift = 0, spin_drift = 0, strain = 0;
  for (std::size_t n = 0; n < r.history.steps.size(); ++n) {
    drift = std::max(drift, std::abs(r.history.steps[n].energy.total - e0));
    spin_drift = std::max(spin_drift, std::abs(r.angular_momentum[n] - L0));
    strain = std::max(strain, r.history.steps[n].energy.elastic);
  }
  EXPECT_GT(strain, 1e-3 * e0);
  EXPECT_LT(drift, 1e-9 * e0);
  EXPECT_LT(spin_drift, 1e-9 * std::abs(L0));
}

struct ImpactRun {
  MarchHistory history;
  std::vector<DynamicState> states;
  Eigen::VectorXd weight;
  Eigen::SparseMatrix<double> mass;
};

// The ring (centre (0, 10.3), thrown at (2, -6) m/s) hits the plane x2 = 0 at t = 0.05 and leaves.
ImpactRun impact(const std::string& strategy, const ContactLaw& law, bool emm = false,
                 int steps = 120, double k = 0.005) {
  Ring ring({0, 10.3});
  ring.with_contact(law);
  if (emm) ring.with_emm();
  ContactStrategyParameters p;
  p.r = 1e9;
  p.gamma = 1e6;
  p.eps = 1e-10;
  const auto s = make_contact_strategy(strategy, p);
  ImpactRun r;
  r.weight = ring.contact->weight;
  r.mass = ring.mass;
  const DynamicState start = ring.thrown({2, -6}, 0, {0, 0});
  r.states.push_back(start);
  r.history = march_hyperelastic(
      ring.problem(k, AlgorithmicStress::gonzalez), s.get(), options(), start, steps, 0,
      [&](const StepRecord&, const DynamicState& state) { r.states.push_back(state); });
  return r;
}

ContactLaw coulomb(double mu, double depth = 0, FrictionLaw friction = FrictionLaw::coulomb) {
  ContactLaw law;
  law.depth = depth;
  if (mu > 0) {
    law.friction = friction;
    law.mu = mu;
  }
  return law;
}

// Every strategy: the balance E + interface - friction work - wall work constant through the
// impact (Prop. 8.1 with Gonzalez's stress), each step's friction and wall work <= 0, and the
// momentum balance of check 6, M (v_n - v_{n-1}) summed over the nodes = k x the contact forces
// of the step (the internal forces of the step sum to zero), M the march's mass (consistent or
// EMM: check 6 holds for both, the EMM keeping M's row sums).
class ImpactOfEveryStrategy
    : public ::testing::TestWithParam<std::tuple<const char*, double, FrictionLaw, bool>> {};

TEST_P(ImpactOfEveryStrategy, BalancesEnergyAndMomentumThroughTheImpact) {
  const auto [strategy, mu, friction, emm] = GetParam();
  const ImpactRun r =
      impact(strategy, coulomb(mu, std::string(strategy) == "ipm" ? 0.002 : 0.0, friction), emm);
  ASSERT_TRUE(r.history.converged) << r.history.failure << strategy;
  std::vector<EnergyRecord> E;
  for (const StepRecord& step : r.history.steps)
    E.push_back(step.energy);
  const double e0 = E[0].total;
  const double momentum = r.mass.sum() / 2 * std::sqrt(40.0); // |M v| of the throw (2, -6)
  int contact_steps = 0;
  for (std::size_t n = 1; n < E.size(); ++n) {
    const double balance = E[n].total + E[n].interface - E[n].friction_work - E[n].wall_work;
    EXPECT_NEAR(balance, e0, 1e-8 * e0) << strategy << " step " << n;
    if (std::string(strategy) != "two-step") { // (b)'s midpoint persistency may push back
      EXPECT_LE(E[n].wall_work - E[n - 1].wall_work, 1e-9 * e0) << strategy << " step " << n;
    }
    EXPECT_LE(E[n].friction_work - E[n - 1].friction_work, 1e-9 * e0) << strategy << " step " << n;
    contact_steps += E[n].active_nodes > 0 ? 1 : 0;

    // Check 6: the internal forces of the step sum to zero, so the momentum change of the step
    // is k times the contact forces' resultant, (-sum T, sum N) on this plane.
    const Eigen::VectorXd dp = r.mass * (r.states[n].v - r.states[n - 1].v);
    Eigen::Vector2d change = Eigen::Vector2d::Zero();
    for (Eigen::Index i = 0; i < dp.size(); i += 2)
      change += dp.segment<2>(i);
    // Rounding of v = (2 / k)(u_n - u_{n-1}) - v_{n-1}: 1e-12 of the momentum.
    const double k = 0.005, scale = k * std::abs(E[n].normal_force) + 1e-4 * momentum;
    EXPECT_NEAR(change.x(), -k * E[n].tangential_force, 1e-8 * scale) << strategy << " " << n;
    EXPECT_NEAR(change.y(), k * E[n].normal_force, 1e-8 * scale) << strategy << " step " << n;
    // Check 7 per step: |sum T| <= max mu sum N (2 mu0 for mu2).
    const double most = friction == FrictionLaw::mu2 ? 2 * mu : mu;
    EXPECT_LE(std::abs(E[n].tangential_force), most * E[n].normal_force * (1 + 1e-9) + 1e-12);
  }
  EXPECT_GT(contact_steps, 3) << strategy; // it did hit
  if (mu > 0) {
    EXPECT_LT(E.back().friction_work, -1e-4 * e0) << strategy; // friction did work
  }
}

INSTANTIATE_TEST_SUITE_P(
    HyperelasticRing, ImpactOfEveryStrategy,
    ::testing::Values(std::make_tuple("signorini", 0.0, FrictionLaw::none, false),
                      std::make_tuple("specific-penalty", 0.0, FrictionLaw::none, false),
                      std::make_tuple("two-step", 0.0, FrictionLaw::none, false),
                      std::make_tuple("ipm", 0.0, FrictionLaw::none, false),
                      std::make_tuple("signorini", 0.2, FrictionLaw::coulomb, false),
                      std::make_tuple("specific-penalty", 0.2, FrictionLaw::coulomb, false),
                      std::make_tuple("ipm", 0.2, FrictionLaw::coulomb, false),
                      std::make_tuple("ipm", 0.2, FrictionLaw::mu1, false),
                      std::make_tuple("ipm", 0.2, FrictionLaw::mu2, false),
                      // EMM and IPM + EMM with mu1, the scene's deck
                      std::make_tuple("signorini", 0.0, FrictionLaw::none, true),
                      std::make_tuple("ipm", 0.2, FrictionLaw::mu1, true)));

// (3.53) in large deformation: frictionless, the specific penalty's wall work is nil, so
// E + (r / 2) sum w [q]_+^2 is constant, to the Newton tolerance, and IPM keeps the penetration
// below g at every step with its bound reached.
TEST(HyperelasticMarch, SpecificPenaltyConservesAndIpmBoundsThePenetration) {
  const ImpactRun sp = impact("specific-penalty", coulomb(0));
  ASSERT_TRUE(sp.history.converged) << sp.history.failure;
  double deepest = 0;
  const double e0 = sp.history.steps[0].energy.total;
  for (const StepRecord& step : sp.history.steps) {
    const EnergyRecord& e = step.energy;
    EXPECT_NEAR(e.total + e.interface, e0, 1e-9 * e0);
    EXPECT_NEAR(e.wall_work, 0.0, 1e-9 * e0);
    deepest = std::max(deepest, e.max_penetration);
  }
  EXPECT_GT(deepest, 0.003); // the foundation did store energy, and more than IPM's g

  const double g = 0.002;
  const ImpactRun ipm = impact("ipm", coulomb(0, g));
  ASSERT_TRUE(ipm.history.converged) << ipm.history.failure;
  double ipm_deepest = 0;
  for (const StepRecord& step : ipm.history.steps) {
    EXPECT_LE(step.energy.max_penetration, g * (1 + 1e-8));
    ipm_deepest = std::max(ipm_deepest, step.energy.max_penetration);
  }
  EXPECT_GT(ipm_deepest, 0.99 * g);
  EXPECT_LT(ipm.history.steps.back().energy.wall_work, 0.0); // the wall dissipates (l.15560)
}

// Fig 8.8's claim in small: with IPM, mu2 (2 mu0 falling to mu0 over the asperities) dissipates
// more by friction than mu1 (0 rising to mu0), and both less than... nothing: each only
// dissipates. The ring slides at 2 m/s as it lands.
TEST(HyperelasticMarch, Mu2DissipatesMoreThanMu1) {
  const ImpactRun mu1 = impact("ipm", coulomb(0.2, 0.002, FrictionLaw::mu1));
  const ImpactRun mu2 = impact("ipm", coulomb(0.2, 0.002, FrictionLaw::mu2));
  ASSERT_TRUE(mu1.history.converged && mu2.history.converged);
  const double w1 = mu1.history.steps.back().energy.friction_work;
  const double w2 = mu2.history.steps.back().energy.friction_work;
  EXPECT_LT(w1, 0.0);
  EXPECT_LT(w2, 1.2 * w1); // more negative: more dissipated (1.4x here)
}

} // namespace
} // namespace sig
