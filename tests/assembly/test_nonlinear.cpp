// The hyperelastic bulk on triangles and on tetrahedra (one code path, the mesh's dimension):
// internal force against finite differences of the energy, tangent against finite differences of
// the force, the small-strain limit against the Hooke stiffness of assemble_stiffness, rigid
// motions without force, the tangent refilled in place; and a midpoint time step's force:
// Gonzalez's energy identity on the whole body, no moment (the angular momentum) with either
// stress, its tangent against finite differences. 3D on gmsh's unit cube (27 nodes).
#include "assembly/nonlinear.hpp"
#include "assembly/system.hpp"
#include "core/error.hpp"
#include "material/algorithmic_stress.hpp"
#include "material/ciarlet_geymonat.hpp"
#include "material/mili.hpp"
#include "material/saint_venant_kirchhoff.hpp"
#include "mesh/gmsh.hpp"
#include "test_meshes.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <random>

namespace sig {
namespace {

SubdomainMaterial hyperelastic_entry(int subdomain, std::shared_ptr<const HyperelasticLaw> law,
                                     double thickness) {
  SubdomainMaterial m;
  m.subdomain = subdomain;
  m.hooke = law->linearized();
  m.hyperelastic = std::move(law);
  m.thickness = thickness;
  return m;
}

// Sub-domain 1 Ciarlet-Geymonat (thesis values), sub-domain 2 Saint Venant-Kirchhoff.
MaterialTable two_laws(PlaneMode plane, double thickness) {
  MaterialTable table;
  table.entries = {
      hyperelastic_entry(1, std::make_shared<CiarletGeymonat>(0.5, 0.005, 0.35, plane), thickness),
      hyperelastic_entry(2, std::make_shared<SaintVenantKirchhoff>(3.0, 0.3, plane), thickness)};
  return table;
}

Eigen::VectorXd random_displacement(int dofs, double size, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-size, size);
  Eigen::VectorXd u(dofs);
  for (int i = 0; i < dofs; ++i)
    u(i) = value(rng);
  return u;
}

// A stretch and shear of the whole body plus noise: moderate, but far from small strain.
Eigen::VectorXd moderate_displacement(const Mesh& mesh, unsigned seed) {
  const int d = mesh.dim;
  Eigen::Matrix3d H;
  H << 0.25, 0.15, 0.1, -0.1, -0.2, 0.2, 0.05, -0.15, -0.2;
  Eigen::VectorXd u = random_displacement(d * mesh.num_nodes(), 0.02, seed);
  for (int n = 0; n < mesh.num_nodes(); ++n)
    u.segment(d * n, d) += H.topLeftCorner(d, d) * mesh.nodes[n];
  return u;
}

/// The unit cube of gmsh's tetrahedra (27 nodes) and the ring's Ciarlet-Geymonat law on it.
Mesh cube() {
  return read_gmsh(std::filesystem::path(SIG_SOURCE_DIR) / "tests" / "fuzz" / "corpus" / "gmsh" /
                   "box_v41_ascii.msh");
}

MaterialTable ciarlet_geymonat_3d(const Mesh& mesh) {
  MaterialTable table;
  for (int subdomain : mesh.subdomains())
    table.entries.push_back(
        hyperelastic_entry(subdomain, std::make_shared<CiarletGeymonat>(0.5, 0.005, 0.35), 1.0));
  return table;
}

/// Central differences of `force` (a function of u) at u, one column per dof.
template <typename Force> Eigen::MatrixXd jacobian(const Force& force, const Eigen::VectorXd& u) {
  const double h = 1e-6;
  Eigen::MatrixXd J(u.size(), u.size());
  for (int j = 0; j < u.size(); ++j) {
    Eigen::VectorXd plus = u, minus = u;
    plus(j) += h;
    minus(j) -= h;
    J.col(j) = (force(plus) - force(minus)) / (2 * h);
  }
  return J;
}

void expect_force_is_the_energy_gradient(const Mesh& mesh, const MaterialTable& table,
                                         const Eigen::VectorXd& u) {
  const SparsityPattern pattern(mesh);
  HyperelasticState state;
  assemble_hyperelastic(mesh, table, pattern, u, state);
  EXPECT_NEAR(state.energy, hyperelastic_energy(mesh, table, u), 1e-14 * state.energy);
  const double h = 1e-6;
  Eigen::VectorXd numeric(u.size());
  for (int i = 0; i < u.size(); ++i) {
    Eigen::VectorXd plus = u, minus = u;
    plus(i) += h;
    minus(i) -= h;
    numeric(i) =
        (hyperelastic_energy(mesh, table, plus) - hyperelastic_energy(mesh, table, minus)) /
        (2 * h);
  }
  EXPECT_LT((state.internal_force - numeric).norm(), 1e-6 * state.internal_force.norm());
}

void expect_tangent_is_the_force_derivative(const Mesh& mesh, const MaterialTable& table,
                                            const Eigen::VectorXd& u) {
  const SparsityPattern pattern(mesh);
  HyperelasticState state;
  assemble_hyperelastic(mesh, table, pattern, u, state);
  const Eigen::MatrixXd K(state.tangent);
  const Eigen::MatrixXd numeric = jacobian(
      [&](const Eigen::VectorXd& v) {
        HyperelasticState s;
        assemble_hyperelastic_force(mesh, table, v, s);
        return Eigen::VectorXd(s.internal_force);
      },
      u);
  EXPECT_LT((K - numeric).norm(), 1e-6 * K.norm());
  EXPECT_LT((K - K.transpose()).norm(), 1e-13 * K.norm());
}

/// The tangent at rest is assemble_stiffness's with `hooke`, and rest carries no energy or force.
void expect_rest_tangent_is_hooke(const Mesh& mesh, const MaterialTable& table,
                                  const MaterialTable& hooke) {
  const SparsityPattern pattern(mesh);
  HyperelasticState state;
  assemble_hyperelastic(mesh, table, pattern, Eigen::VectorXd::Zero(pattern.num_dofs()), state);
  const Eigen::SparseMatrix<double> K = assemble_stiffness(mesh, hooke, pattern);
  EXPECT_LT((state.tangent - K).norm(), 1e-10 * K.norm());
  EXPECT_EQ(state.energy, 0.0);
  EXPECT_EQ(state.internal_force.norm(), 0.0);
}

/// One time step from u0 to u1: G . (u1 - u0) = E(u1) - E(u0) with Gonzalez's stress (the
/// discrete energy identity that makes the march conserve E), missed by the midpoint stress;
/// no moment about the origin at the midpoint positions, sum_a x_m,a x G_a = 0, with either
/// stress (the angular momentum); the step's tangent the derivative of its force in u1.
void expect_step_identities(const Mesh& mesh, const MaterialTable& table, const Eigen::VectorXd& u0,
                            const Eigen::VectorXd& u1) {
  const int d = mesh.dim;
  const SparsityPattern pattern(mesh);
  const PreviousStrain previous = previous_strain(mesh, table, u0);
  const double E0 = hyperelastic_energy(mesh, table, u0), E1 = hyperelastic_energy(mesh, table, u1);
  for (AlgorithmicStress kind : {AlgorithmicStress::gonzalez, AlgorithmicStress::midpoint}) {
    SCOPED_TRACE(to_string(kind));
    HyperelasticState step;
    assemble_hyperelastic_step(mesh, table, pattern, previous, kind, u1, step, true);
    EXPECT_NEAR(step.energy, E1, 1e-14 * E1);
    const double identity = step.internal_force.dot(u1 - u0) - (E1 - E0);
    if (kind == AlgorithmicStress::gonzalez)
      EXPECT_LT(std::abs(identity), 1e-12 * std::abs(E1 - E0));
    else
      EXPECT_GT(std::abs(identity), 1e-4 * std::abs(E1 - E0));
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();
    double scale = 0;
    for (int n = 0; n < mesh.num_nodes(); ++n) {
      Eigen::Vector3d x = Eigen::Vector3d::Zero(), G = Eigen::Vector3d::Zero();
      x.head(d) = mesh.nodes[n] + 0.5 * (u0 + u1).segment(d * n, d);
      G.head(d) = step.internal_force.segment(d * n, d);
      moment += x.cross(G);
      scale += x.norm() * G.norm();
    }
    EXPECT_LT(moment.norm(), 1e-13 * scale);
    const Eigen::MatrixXd numeric = jacobian(
        [&](const Eigen::VectorXd& v) {
          HyperelasticState s;
          assemble_hyperelastic_step(mesh, table, pattern, previous, kind, v, s, false);
          return Eigen::VectorXd(s.internal_force);
        },
        u1);
    const Eigen::MatrixXd K(step.tangent);
    EXPECT_LT((K - numeric).norm(), 1e-6 * K.norm());
  }
}

/// u1 of a step from u0: the body at u1's shape (moderate_displacement), rotated by Q about
/// the origin (x1 = Q (X + u) for d = 3, its in-plane block in 2D).
Eigen::VectorXd rotated(const Mesh& mesh, const Eigen::VectorXd& u, const Eigen::Matrix3d& Q) {
  const int d = mesh.dim;
  Eigen::VectorXd out(u.size());
  for (int n = 0; n < mesh.num_nodes(); ++n)
    out.segment(d * n, d) = Q.topLeftCorner(d, d) * (mesh.nodes[n] + u.segment(d * n, d)) -
                            Eigen::VectorXd(mesh.nodes[n]);
  return out;
}

class NonlinearAssembly : public ::testing::TestWithParam<PlaneMode> {};

TEST_P(NonlinearAssembly, InternalForceIsTheDerivativeOfTheEnergy) {
  const Mesh mesh = test::square_mesh(3, 3, 1.0, 0.25, 2);
  expect_force_is_the_energy_gradient(mesh, two_laws(GetParam(), 0.5),
                                      moderate_displacement(mesh, 1));
}

TEST_P(NonlinearAssembly, TangentIsTheDerivativeOfTheInternalForce) {
  const Mesh mesh = test::square_mesh(3, 3, 1.0, 0.25, 2);
  expect_tangent_is_the_force_derivative(mesh, two_laws(GetParam(), 0.5),
                                         moderate_displacement(mesh, 2));
}

TEST_P(NonlinearAssembly, TimeStepKeepsTheEnergyIdentityAndTheAngularMomentum) {
  const Mesh mesh = test::square_mesh(3, 3, 1.0, 0.25, 2);
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).matrix();
  expect_step_identities(mesh, two_laws(GetParam(), 0.5), moderate_displacement(mesh, 2),
                         rotated(mesh, moderate_displacement(mesh, 3), Q));
}

TEST_P(NonlinearAssembly, TangentAtRestIsTheHookeStiffness) {
  const Mesh mesh = test::square_mesh(4, 3, 2.0, 0.25, 2);
  const double thickness = 0.7;
  const MaterialTable table = two_laws(GetParam(), thickness);
  // Hooke's laws written out independently: Ciarlet-Geymonat lambda = 4 (a + c2) = 1.42,
  // mu = 2 (c1 + c2) = 1.01; SVK the same E, nu.
  MaterialTable hooke;
  hooke.entries.resize(2);
  const double lambda = 1.42, mu = 1.01;
  hooke.entries[0].subdomain = 1;
  hooke.entries[0].hooke = {mu * (3 * lambda + 2 * mu) / (lambda + mu),
                            lambda / (2 * (lambda + mu)), GetParam()};
  hooke.entries[1].subdomain = 2;
  hooke.entries[1].hooke = {3.0, 0.3, GetParam()};
  for (auto& entry : hooke.entries)
    entry.thickness = thickness;
  expect_rest_tangent_is_hooke(mesh, table, hooke);
}

TEST_P(NonlinearAssembly, RigidMotionHasNoInternalForce) {
  const Mesh mesh = test::square_mesh(4, 4, 1.0, 0.25, 2);
  const MaterialTable table = two_laws(GetParam(), 1.0);
  const SparsityPattern pattern(mesh);
  // A finite rotation of 0.8 rad plus a translation: u = (R - I) X + c.
  Eigen::Matrix2d R;
  R << std::cos(0.8), -std::sin(0.8), std::sin(0.8), std::cos(0.8);
  Eigen::VectorXd u(2 * mesh.num_nodes());
  for (int n = 0; n < mesh.num_nodes(); ++n)
    u.segment<2>(2 * n) =
        (R - Eigen::Matrix2d::Identity()) * mesh.nodes[n] + Eigen::Vector2d(0.3, -1.1);
  HyperelasticState state;
  assemble_hyperelastic(mesh, table, pattern, u, state);
  // Scale: the force of a 10 % uniaxial stretch of the same body.
  HyperelasticState stretched;
  Eigen::VectorXd v = Eigen::VectorXd::Zero(u.size());
  for (int n = 0; n < mesh.num_nodes(); ++n)
    v(2 * n) = 0.1 * mesh.nodes[n].x();
  assemble_hyperelastic(mesh, table, pattern, v, stretched);
  EXPECT_LT(state.internal_force.norm(), 1e-12 * stretched.internal_force.norm());
  EXPECT_LT(std::abs(state.energy), 1e-12 * stretched.energy);
  // The rotated tangent is the rest tangent turned: same spectrum.
  HyperelasticState rest;
  assemble_hyperelastic(mesh, table, pattern, Eigen::VectorXd::Zero(u.size()), rest);
  const Eigen::VectorXd e1 =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(state.tangent)).eigenvalues();
  const Eigen::VectorXd e0 =
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Eigen::MatrixXd(rest.tangent)).eigenvalues();
  EXPECT_LT((e1 - e0).norm(), 1e-10 * e0.norm());
}

INSTANTIATE_TEST_SUITE_P(PlaneModes, NonlinearAssembly,
                         ::testing::Values(PlaneMode::strain, PlaneMode::stress),
                         [](const auto& info) {
                           return std::string(info.param == PlaneMode::strain ? "PlaneStrain"
                                                                              : "PlaneStress");
                         });

TEST(NonlinearAssembly3d, ForceTangentAndRestOnTetrahedra) {
  const Mesh mesh = cube();
  ASSERT_EQ(mesh.dim, 3);
  const MaterialTable table = ciarlet_geymonat_3d(mesh);
  expect_force_is_the_energy_gradient(mesh, table, moderate_displacement(mesh, 1));
  expect_tangent_is_the_force_derivative(mesh, table, moderate_displacement(mesh, 2));
  // Its Hooke law: the linearized law (lambda = 1.42, mu = 1.01) in 3D.
  expect_rest_tangent_is_hooke(mesh, table, table);
}

TEST(NonlinearAssembly3d, TimeStepKeepsTheEnergyIdentityAndTheAngularMomentum) {
  const Mesh mesh = cube();
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  expect_step_identities(mesh, ciarlet_geymonat_3d(mesh), moderate_displacement(mesh, 2),
                         rotated(mesh, moderate_displacement(mesh, 3), Q));
}

TEST(NonlinearAssemblyPattern, TangentIsRefilledInPlace) {
  const Mesh mesh = test::square_mesh(3, 2, 1.0, 0.2, 2);
  const MaterialTable table = two_laws(PlaneMode::strain, 1.0);
  const SparsityPattern pattern(mesh);
  HyperelasticState state;
  const Eigen::VectorXd u1 = moderate_displacement(mesh, 3);
  const Eigen::VectorXd u2 = moderate_displacement(mesh, 4);
  assemble_hyperelastic(mesh, table, pattern, u1, state);
  const double* values = state.tangent.valuePtr();
  const int* inner = state.tangent.innerIndexPtr();
  assemble_hyperelastic(mesh, table, pattern, u2, state);
  EXPECT_EQ(state.tangent.valuePtr(), values);
  EXPECT_EQ(state.tangent.innerIndexPtr(), inner);
  // Refilled, not accumulated: equal to a fresh assembly at u2.
  HyperelasticState fresh;
  assemble_hyperelastic(mesh, table, pattern, u2, fresh);
  EXPECT_EQ((state.tangent - fresh.tangent).norm(), 0.0);
  EXPECT_EQ((state.internal_force - fresh.internal_force).norm(), 0.0);
  EXPECT_EQ(state.tangent.nonZeros(), pattern.nnz());
}

TEST(NonlinearAssemblyPattern, InvertedTriangleAndLinearLawAreReported) {
  const Mesh mesh = test::square_mesh(2, 2, 1.0, 0.0, 2);
  const MaterialTable table = two_laws(PlaneMode::strain, 1.0);
  const SparsityPattern pattern(mesh);
  // Mirror the body through x = 0: every triangle is inverted.
  Eigen::VectorXd u = Eigen::VectorXd::Zero(2 * mesh.num_nodes());
  for (int n = 0; n < mesh.num_nodes(); ++n)
    u(2 * n) = -2.0 * mesh.nodes[n].x();
  EXPECT_EQ(hyperelastic_energy(mesh, table, u), std::numeric_limits<double>::infinity());
  HyperelasticState state;
  EXPECT_THROW(assemble_hyperelastic(mesh, table, pattern, u, state), Error);

  MaterialTable linear = table;
  linear.entries[1].hyperelastic.reset();
  EXPECT_THROW(hyperelastic_energy(mesh, linear, Eigen::VectorXd::Zero(u.size())), Error);
}

} // namespace
} // namespace sig
