// The hyperelastic bulk on tetrahedra (assembly/nonlinear.hpp in 3D, the 2D code path templated
// on the mesh's dimension): on gmsh's unit cube (27 nodes) with the Ciarlet-Geymonat law, the
// internal force against finite differences of the energy, the tangent against finite
// differences of the force, the tangent at rest against the 3D Hooke stiffness; and a midpoint
// time step's force: Gonzalez's energy identity on the whole body, its tangent against finite
// differences, and no moment about the origin for either stress (the angular momentum).
#include "assembly/nonlinear.hpp"
#include "assembly/system.hpp"
#include "material/algorithmic_stress.hpp"
#include "material/ciarlet_geymonat.hpp"
#include "material/mili.hpp"
#include "mesh/gmsh.hpp"
#include "mesh/mesh.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <random>

namespace sig {
namespace {

Mesh cube() {
  return read_gmsh(std::filesystem::path(SIG_SOURCE_DIR) / "tests" / "fuzz" / "corpus" / "gmsh" /
                   "box_v41_ascii.msh");
}

/// The ring's Ciarlet-Geymonat law on every sub-domain of `mesh`.
MaterialTable ciarlet_geymonat(const Mesh& mesh) {
  MaterialTable table;
  for (int subdomain : mesh.subdomains()) {
    SubdomainMaterial m;
    m.subdomain = subdomain;
    const auto law = std::make_shared<CiarletGeymonat>(0.5, 0.005, 0.35);
    m.hooke = law->linearized();
    m.hyperelastic = law;
    table.entries.push_back(m);
  }
  return table;
}

/// A stretch, shear and rotation of the whole cube plus noise: far from small strain.
Eigen::VectorXd moderate_displacement(const Mesh& mesh, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> noise(-0.02, 0.02);
  Eigen::Matrix3d H;
  H << 0.25, 0.15, -0.1, -0.2, 0.1, 0.2, 0.05, -0.15, -0.2;
  Eigen::VectorXd u(3 * mesh.num_nodes());
  for (int n = 0; n < mesh.num_nodes(); ++n)
    u.segment<3>(3 * n) =
        H * Eigen::Vector3d(mesh.nodes[n]) + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
  return u;
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

TEST(NonlinearAssembly3d, ForceAndTangentAreTheDerivativesOfTheEnergy) {
  const Mesh mesh = cube();
  ASSERT_EQ(mesh.dim, 3);
  const MaterialTable table = ciarlet_geymonat(mesh);
  const SparsityPattern pattern(mesh);
  const Eigen::VectorXd u = moderate_displacement(mesh, 1);
  HyperelasticState state;
  assemble_hyperelastic(mesh, table, pattern, u, state);
  EXPECT_NEAR(state.energy, hyperelastic_energy(mesh, table, u), 1e-14 * state.energy);
  EXPECT_GT(state.energy, 0.0);

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

  const Eigen::MatrixXd K(state.tangent);
  const Eigen::MatrixXd fd = jacobian(
      [&](const Eigen::VectorXd& v) {
        HyperelasticState s;
        assemble_hyperelastic_force(mesh, table, v, s);
        return Eigen::VectorXd(s.internal_force);
      },
      u);
  EXPECT_LT((K - fd).norm(), 1e-6 * K.norm());
  EXPECT_LT((K - K.transpose()).norm(), 1e-13 * K.norm());
}

TEST(NonlinearAssembly3d, TangentAtRestIsTheHookeStiffness) {
  const Mesh mesh = cube();
  const MaterialTable table = ciarlet_geymonat(mesh);
  const SparsityPattern pattern(mesh);
  HyperelasticState state;
  assemble_hyperelastic(mesh, table, pattern, Eigen::VectorXd::Zero(pattern.num_dofs()), state);
  const Eigen::SparseMatrix<double> K = assemble_stiffness(mesh, table, pattern);
  EXPECT_LT((state.tangent - K).norm(), 1e-10 * K.norm());
  EXPECT_EQ(state.energy, 0.0);
  EXPECT_EQ(state.internal_force.norm(), 0.0);
}

// One time step from u0 to u1 (each a large deformation of the cube, apart by a rotation and a
// stretch): sum of Pi : (F1 - F0) over the body, G . (u1 - u0), is E(u1) - E(u0) with Gonzalez's
// stress (the discrete energy identity that makes the march conserve E); the force has no
// moment about the origin at the midpoint positions, sum_a x_m,a x G_a = 0 (the angular
// momentum), with either stress; and the step's tangent is its derivative in u1.
TEST(NonlinearAssembly3d, TimeStepKeepsTheEnergyIdentityAndTheAngularMomentum) {
  const Mesh mesh = cube();
  const MaterialTable table = ciarlet_geymonat(mesh);
  const SparsityPattern pattern(mesh);
  const Eigen::VectorXd u0 = moderate_displacement(mesh, 2);
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 3).normalized()).matrix();
  Eigen::VectorXd u1 = moderate_displacement(mesh, 3);
  for (int n = 0; n < mesh.num_nodes(); ++n) { // x1 = Q x, then u1 = x1 - X
    const Eigen::Vector3d X = mesh.nodes[n];
    u1.segment<3>(3 * n) = Q * (X + u1.segment<3>(3 * n)) - X;
  }
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
      EXPECT_GT(std::abs(identity), 1e-4 * std::abs(E1 - E0)); // the midpoint stress misses it
    Eigen::Vector3d moment = Eigen::Vector3d::Zero();
    double scale = 0;
    for (int n = 0; n < mesh.num_nodes(); ++n) {
      const Eigen::Vector3d x = Eigen::Vector3d(mesh.nodes[n]) + 0.5 * (u0 + u1).segment<3>(3 * n);
      const Eigen::Vector3d G = step.internal_force.segment<3>(3 * n);
      moment += x.cross(G);
      scale += x.norm() * G.norm();
    }
    EXPECT_LT(moment.norm(), 1e-13 * scale);
    const Eigen::MatrixXd fd = jacobian(
        [&](const Eigen::VectorXd& v) {
          HyperelasticState s;
          assemble_hyperelastic_step(mesh, table, pattern, previous, kind, v, s, false);
          return Eigen::VectorXd(s.internal_force);
        },
        u1);
    const Eigen::MatrixXd K(step.tangent);
    EXPECT_LT((K - fd).norm(), 1e-6 * K.norm());
  }
}

} // namespace
} // namespace sig
