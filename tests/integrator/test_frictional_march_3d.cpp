// Friction in the linear march of a 3D body (integrator/elastodynamic_march.hpp, issue 28): two
// slips a contact node, along the tangents t1, t2 of its contact frame, the tangential force in
// the disc of radius mu N. Checked where the 3D march must reduce to the 2D one exactly: the
// linear disc of test_frictional_march.cpp, thrown obliquely onto the plane x2 = 0 with Coulomb
// friction, embedded in 3D -- each node gets a third displacement, out of the plane, with a
// stiffness and a mass of its own and no coupling, at rest and unloaded -- and the plane becomes
// x3 = 0 with the normal (0, 0, 1) and that normal's contact frame (whose tangents need not be
// the in-plane direction and the out-of-plane one: the disc projection does not see the frame's
// turn). Nothing drives the third component, the force in the disc opposes an in-plane slip,
// so with every strategy:
//  - every state of the 3D march is the 2D one on the in-plane components, to the Newton
//    tolerance (eps = 1e-10 of the driver's test (iv): 1e-8 of the displacement and velocity
//    scale), the out-of-plane ones 0 to that tolerance;
//  - every step's energies, friction work and wall work are the 2D march's to 1e-9 of E0, so
//    the 3D balance E + interface - friction work - wall work = E0 holds to 1e-9 of E0, and
//    the friction work of every step is <= 0;
//  - each node's tangential force |T| (two components in 3D) is the 2D |T| and stays in the
//    cone |T| <= mu N.
#include "assembly/dirichlet.hpp"
#include "contact/contact_elements.hpp"
#include "contact/contact_law.hpp"
#include "contact/obstacle.hpp"
#include "integrator/contact_strategy.hpp"
#include "integrator/elastodynamic_march.hpp"
#include "mesh/generators.hpp"
#include "stages/march_inputs.hpp"
#include "test_bodies.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace sig {
namespace {

constexpr double kRadius = 1.0, kGap = 0.02, k = 0.005, kMu = 0.3, kAllowed = 0.002;
constexpr double kThreshold = 0.5; // tresca's bound, a traction (N / weight)
constexpr int kSteps = 60;

/// 2D dof a (node a / 2, component a % 2) -> its 3D dof: x1 -> x1, x2 -> x3.
int lifted(int a) {
  return 3 * (a / 2) + (a % 2 == 0 ? 0 : 2);
}

/// The 2D matrix A on the in-plane dofs of the 3D numbering, `out_of_plane` on the third
/// component of each node (diagonal, uncoupled). Every component of a node coupled to every
/// component of a node it couples with (stored zeros): the nodal pattern of an assembled matrix,
/// which the contact condensation turns into the nodes' frames in place.
Eigen::SparseMatrix<double> lift(const Eigen::SparseMatrix<double>& A, double out_of_plane) {
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index j = 0; j < A.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) {
      const auto a = static_cast<int>(it.row()), b = static_cast<int>(it.col());
      entries.emplace_back(lifted(a), lifted(b), it.value());
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          entries.emplace_back(3 * (a / 2) + r, 3 * (b / 2) + c, 0.0);
    }
  const auto nodes = A.rows() / 2;
  for (Eigen::Index i = 0; i < nodes; ++i)
    entries.emplace_back(3 * i + 1, 3 * i + 1, out_of_plane);
  Eigen::SparseMatrix<double> B(3 * nodes, 3 * nodes);
  B.setFromTriplets(entries.begin(), entries.end());
  return B;
}

/// The rows of a 2D operator (p x 2D dofs) on the 3D dofs of `nodes` nodes.
Eigen::SparseMatrix<double> lift_columns(const Eigen::SparseMatrix<double>& A, int nodes) {
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index j = 0; j < A.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it)
      entries.emplace_back(static_cast<int>(it.row()), lifted(static_cast<int>(it.col())),
                           it.value());
  Eigen::SparseMatrix<double> B(A.rows(), 3 * nodes);
  B.setFromTriplets(entries.begin(), entries.end());
  return B;
}

/// A vector of the 2D dofs on the 3D numbering (0 out of the plane).
Eigen::VectorXd lift(const Eigen::VectorXd& x) {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(3 * (x.size() / 2));
  for (Eigen::Index a = 0; a < x.size(); ++a)
    y[lifted(static_cast<int>(a))] = x[a];
  return y;
}

struct Marched {
  MarchHistory history;
  std::vector<DynamicState> states; ///< every step's, from step 0
};

Marched march_on(const TimeScheme& scheme, const ContactBoundary& boundary,
                 const std::string& strategy, const DynamicState& initial) {
  ContactStrategyParameters p;
  p.r = 1e4;     // the foundation per unit area: 100 E per unit length
  p.gamma = 1e4; // PDAS's parameter, of the order of a node's stiffness in the step
  p.eps = 1e-10;
  Marched r;
  r.states.push_back(initial);
  r.history = march_with_contact(
      scheme, boundary, *make_contact_strategy(strategy, p), initial, kSteps, 0,
      [&r](const StepRecord&, const DynamicState& state) { r.states.push_back(state); });
  return r;
}

class ObliqueDrop3d
    : public ::testing::TestWithParam<std::tuple<const char*, FrictionLaw, double>> {};

TEST_P(ObliqueDrop3d, IsThe2dMarchWhenThe3dBodyReducesToIt) {
  const auto [strategy, friction, depth] = GetParam();
  ContactLaw law;
  law.depth = depth;
  law.friction = friction;
  law.mu = kMu;
  law.threshold = kThreshold;
  // The 2D disc (E = 100, rho = 1, 32 segments) kGap above the plane, its bottom quarter the
  // contact boundary; thrown at (1, -2).
  const Mesh mesh = disc({0.0, kRadius + kGap}, kRadius, 32);
  const LinearSystem system = test::free_body_system(mesh, test::unit_material(100.0));
  const ReducedSystem reduced = reduce(system);
  ASSERT_EQ(reduced.num_free(), system.num_dofs()); // no Dirichlet dof: the numbering is 2 i + c
  const ContactElements elements = build_contact_elements(mesh, 3, HalfPlane({0, 0}, {0, 1}), law);
  const ContactBoundary plane = contact_boundary(elements, mesh, reduced);
  ASSERT_EQ(plane.tangential.rows(), plane.size());
  Eigen::VectorXd v(system.num_dofs());
  for (int i = 0; i < mesh.num_nodes(); ++i)
    v.segment<2>(2 * i) = Eigen::Vector2d(1.0, -2.0);
  const DynamicState initial{0.0, Eigen::VectorXd::Zero(v.size()), v};
  const Elastodynamics flat = reduced_elastodynamics(reduced, system.M);
  const auto scheme = make_time_scheme("midpoint", flat, k, "cholmod");

  // The same body in 3D: the out-of-plane components with the diagonal stiffness 50 and mass
  // 0.01 of their own; the plane x3 = 0, its frame's two tangents at every node.
  Elastodynamics lifted_problem;
  lifted_problem.K = lift(flat.K, 50.0);
  lifted_problem.M = lift(flat.M, 0.01);
  const auto scheme3 = make_time_scheme("midpoint", lifted_problem, k, "cholmod");
  ContactBoundary space = plane;
  space.B = lift_columns(plane.B, mesh.num_nodes()); // -n . u = -u3 now
  const Eigen::Vector3d normal(0.0, 0.0, 1.0);
  const ContactFrame frame = contact_frame(normal);
  std::vector<Eigen::Triplet<double>> rows;
  for (int i = 0; i < plane.size(); ++i)
    for (int t = 0; t < 2; ++t)
      for (int c = 0; c < 3; ++c)
        rows.emplace_back(2 * i + t, 3 * plane.nodes[static_cast<std::size_t>(i)] + c, frame(c, t));
  space.tangential.resize(2 * plane.size(), 3 * mesh.num_nodes());
  space.tangential.setFromTriplets(rows.begin(), rows.end());
  for (int i = 0; i < plane.size(); ++i) { // the frames by which the step is condensed
    space.first_dof[static_cast<std::size_t>(i)] = 3 * plane.nodes[static_cast<std::size_t>(i)];
    space.frame[static_cast<std::size_t>(i)] = frame;
  }
  const DynamicState initial3{0.0, lift(initial.u), lift(initial.v)};

  const Marched two = march_on(*scheme, plane, strategy, initial);
  const Marched three = march_on(*scheme3, space, strategy, initial3);
  ASSERT_TRUE(two.history.converged) << strategy << " 2D: " << two.history.failure;
  ASSERT_TRUE(three.history.converged) << strategy << " 3D: " << three.history.failure;
  ASSERT_EQ(two.states.size(), three.states.size());
  const double e0 = two.history.steps[0].energy.total;
  const double u_scale = kSteps * k * v.cwiseAbs().maxCoeff(), v_scale = v.cwiseAbs().maxCoeff();
  double worst_state = 0, worst_energy = 0, worst_balance = 0;
  int slipping = 0;
  for (std::size_t n = 1; n < two.states.size(); ++n) {
    const DynamicState &a = two.states[n], &b = three.states[n];
    const double du = (lift(a.u) - b.u).cwiseAbs().maxCoeff() / u_scale;
    const double dv = (lift(a.v) - b.v).cwiseAbs().maxCoeff() / v_scale;
    worst_state = std::max({worst_state, du, dv});
    EXPECT_LE(du, 1e-8) << strategy << " step " << n;
    EXPECT_LE(dv, 1e-8) << strategy << " step " << n;

    const EnergyRecord &e2 = two.history.steps[n].energy, &e3 = three.history.steps[n].energy;
    for (const auto& [name, x, y] : {std::tuple{"total", e2.total, e3.total},
                                     {"interface", e2.interface, e3.interface},
                                     {"friction work", e2.friction_work, e3.friction_work},
                                     {"wall work", e2.wall_work, e3.wall_work}}) {
      worst_energy = std::max(worst_energy, std::abs(x - y) / e0);
      EXPECT_NEAR(x, y, 1e-9 * e0) << strategy << " step " << n << ": " << name;
    }
    const double balance = e3.total + e3.interface - e3.friction_work - e3.wall_work;
    worst_balance = std::max(worst_balance, std::abs(balance - e0) / e0);
    EXPECT_NEAR(balance, e0, 1e-9 * e0) << strategy << " step " << n;
    const double before = three.history.steps[n - 1].energy.friction_work;
    EXPECT_LE(e3.friction_work - before, 1e-15 * e0) << strategy << " step " << n;

    const ContactRecord &c2 = two.history.steps[n].contact, &c3 = three.history.steps[n].contact;
    ASSERT_EQ(c3.tangential_force.size(), 2 * c3.normal_force.size());
    const double most = friction == FrictionLaw::mu2 ? 2 * kMu : kMu;
    const double force_scale = std::max(
        {c2.normal_force.cwiseAbs().maxCoeff(), c2.tangential_force.cwiseAbs().maxCoeff(), 1e-300});
    for (Eigen::Index i = 0; i < c3.normal_force.size(); ++i) {
      const double T3 = c3.tangential_force.template segment<2>(2 * i).norm();
      EXPECT_NEAR(T3, std::abs(c2.tangential_force[i]), 1e-7 * force_scale)
          << strategy << " step " << n << " node " << i;
      const double bound = friction == FrictionLaw::tresca ? kThreshold * plane.setting.weight[i]
                                                           : most * c3.normal_force[i];
      EXPECT_LE(T3, bound * (1 + 1e-9) + 1e-12)
          << strategy << " step " << n << " node " << i; // the cone, the disc of Tresca
      const auto status = c3.friction_status[static_cast<std::size_t>(i)];
      slipping += c3.normal_force[i] > 0 && (status == FrictionStatus::slip_forward ||
                                             status == FrictionStatus::slip_backward);
    }
  }
  EXPECT_GT(slipping, 2) << strategy; // the 3D nodes did slip
  EXPECT_LT(three.history.steps.back().energy.friction_work, -1e-3 * e0) << strategy;
  std::printf("%s %s: 3D against 2D: states %.2g, energies %.2g of E0; 3D balance %.2g of E0, "
              "friction work %.6g (E0 %.6g), %d slipping node-steps\n",
              strategy, to_string(friction).c_str(), worst_state, worst_energy, worst_balance,
              three.history.steps.back().energy.friction_work, e0, slipping);
}

// Every strategy with Coulomb; IPM (g = kAllowed) also with Tresca's bound, which does not
// follow N, and mu2's, which grows with the penetration.
const std::tuple<const char*, FrictionLaw, double> kCases[] = {
    {"signorini", FrictionLaw::coulomb, 0.0},
    {"compliance", FrictionLaw::coulomb, 0.0},
    {"specific-penalty", FrictionLaw::coulomb, 0.0},
    {"two-step", FrictionLaw::coulomb, 0.0},
    {"ipm", FrictionLaw::coulomb, kAllowed},
    {"ipm", FrictionLaw::tresca, kAllowed},
    {"ipm", FrictionLaw::mu2, kAllowed}};
INSTANTIATE_TEST_SUITE_P(LinearDisc, ObliqueDrop3d, ::testing::ValuesIn(kCases));

} // namespace
} // namespace sig
