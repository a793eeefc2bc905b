// The recovery estimator (post/recovery_estimate.hpp) against the true error of a solution known
// in closed form: u = a grad(x^3 - 3 x y^2) = a (3 x^2 - 3 y^2, -6 x y) is the gradient of a
// harmonic function, so div u = 0 and Delta u = 0, and div sigma = mu Delta u + (lambda + mu)
// grad div u = 0 for every Hooke law: no body force, u imposed on the whole boundary of the
// unit square. eps(u) = a (6 x, -6 x, 2 e12 = -12 y) is linear, so the true error
// ||eps(u) - eps(u_h)||_L2 is integrated exactly by the rule the estimator uses.
#include "assembly/dirichlet.hpp"
#include "assembly/pattern.hpp"
#include "assembly/strain.hpp"
#include "assembly/system.hpp"
#include "material/mili.hpp"
#include "mesh/generators.hpp"
#include "post/recovery_estimate.hpp"

#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace sig {
namespace {

constexpr double amplitude = 1e-3;

Eigen::Vector2d exact_u(const Eigen::Vector2d& x) {
  return amplitude * Eigen::Vector2d(3 * x.x() * x.x() - 3 * x.y() * x.y(), -6 * x.x() * x.y());
}

Eigen::Vector3d exact_strain(const Eigen::Vector2d& x) {
  return amplitude * Eigen::Vector3d(6 * x.x(), -6 * x.x(), -12 * x.y());
}

/// The P1 solution on `mesh` with u = exact_u on every boundary node (Hooke E = 100, nu = 0.3).
Eigen::VectorXd solve_manufactured(const Mesh& mesh) {
  MaterialTable table;
  table.entries.resize(1);
  table.entries[0].hooke = {100.0, 0.3, PlaneMode::strain};
  LinearSystem system;
  system.K = assemble_stiffness(mesh, table, SparsityPattern(mesh));
  system.f = Eigen::VectorXd::Zero(system.K.rows());
  std::set<int> boundary;
  for (const Facet& e : mesh.facets)
    boundary.insert({e.node[0], e.node[1]});
  system.dirichlet_values.resize(2 * static_cast<int>(boundary.size()));
  for (int node : boundary)
    for (int c = 0; c < 2; ++c) {
      system.dirichlet_values(static_cast<int>(system.dirichlet_dofs.size())) =
          exact_u(mesh.nodes[node])(c);
      system.dirichlet_dofs.push_back(2 * node + c);
    }
  const ReducedSystem reduced = reduce(system);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(reduced.K);
  EXPECT_EQ(ldlt.info(), Eigen::Success);
  return reduced.expand(ldlt.solve(reduced.f));
}

/// ||eps(u) - eps(u_h)||_L2, exact: the difference is linear on each triangle.
double true_error(const Mesh& mesh, const Eigen::VectorXd& u_h) {
  const std::vector<Eigen::Vector3d> strains = element_strains(mesh, u_h);
  double sum = 0;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    std::array<Eigen::Vector3d, 3> difference;
    for (int i = 0; i < 3; ++i)
      difference[i] = exact_strain(mesh.nodes[mesh.cells[t][i]]) - strains[t];
    sum += linear_strain_square_integral(0.5 * signed_double_area(mesh, t), difference);
  }
  return std::sqrt(sum);
}

TEST(RecoveryEstimate, IntegralOfALinearStrainIsExact) {
  // On the unit right triangle, g = (x, 0, 0): integral of x^2 = 1/12.
  const std::array<Eigen::Vector3d, 3> g = {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
                                            Eigen::Vector3d(0, 0, 0)};
  EXPECT_NEAR(linear_strain_square_integral(0.5, g), 1.0 / 12, 1e-15);
  // A shear counts twice as its engineering value squared over 2: (2 e12)^2 / 2 = 2 e12^2.
  const std::array<Eigen::Vector3d, 3> shear = {Eigen::Vector3d(0, 0, 2), Eigen::Vector3d(0, 0, 2),
                                                Eigen::Vector3d(0, 0, 2)};
  EXPECT_NEAR(linear_strain_square_integral(0.5, shear), 0.5 * 2.0, 1e-15);
}

TEST(RecoveryEstimate, VanishesOnAConstantStrain) {
  // A linear displacement: its strain is recovered exactly, so no error is estimated.
  const Mesh mesh = rectangle(2.0, 1.0, 6, 3);
  Eigen::VectorXd u(2 * mesh.num_nodes());
  for (int i = 0; i < mesh.num_nodes(); ++i)
    u.segment<2>(2 * i) = Eigen::Vector2d(1e-3 * mesh.nodes[i].x() - 2e-3 * mesh.nodes[i].y(),
                                          5e-4 * mesh.nodes[i].x());
  const ErrorIndicators e = recovery_indicators(mesh, u);
  EXPECT_LT(e.estimate, 1e-15);
  EXPECT_EQ(e.eta.size(), mesh.cells.size());
}

TEST(RecoveryEstimate, RecoveryIsPerSubdomain) {
  // Two sub-domains with a strain jump between them: averaged across the interface, the
  // recovery would see an error where the P1 solution is exact on each side.
  Mesh mesh = rectangle(2.0, 1.0, 4, 2);
  Eigen::VectorXd u(2 * mesh.num_nodes());
  for (int t = 0; t < mesh.num_cells(); ++t) {
    double cx = 0;
    for (int v : mesh.cells[t])
      cx += mesh.nodes[v].x() / 3;
    mesh.subdomain[t] = cx < 1 ? 1 : 2;
  }
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    const double x = mesh.nodes[i].x(); // u1 = x on the left, 1 + 3 (x - 1) on the right
    u.segment<2>(2 * i) = Eigen::Vector2d(x < 1 ? x : 1 + 3 * (x - 1), 0.0);
  }
  EXPECT_LT(recovery_indicators(mesh, u).estimate, 1e-13);
}

TEST(RecoveryEstimate, EffectivityAndRateOnASmoothSolution) {
  double previous_error = 0, previous_estimate = 0;
  for (int n : {4, 8, 16, 32}) {
    const Mesh mesh = rectangle(1.0, 1.0, n, n);
    const Eigen::VectorXd u_h = solve_manufactured(mesh);
    const double error = true_error(mesh, u_h);
    const double estimate = recovery_indicators(mesh, u_h).estimate;
    const double effectivity = estimate / error;
    EXPECT_GT(effectivity, 0.3) << "n = " << n;
    EXPECT_LT(effectivity, 3.0) << "n = " << n;
    if (n > 4) {
      // h halves: the error falls as h^1, and the estimate with it.
      const double error_rate = std::log2(previous_error / error);
      const double estimate_rate = std::log2(previous_estimate / estimate);
      EXPECT_NEAR(error_rate, 1.0, 0.1) << "n = " << n;
      EXPECT_NEAR(estimate_rate, error_rate, 0.1) << "n = " << n;
    }
    std::printf("n = %2d: error %.6e, estimate %.6e, effectivity %.4f\n", n, error, estimate,
                effectivity);
    previous_error = error;
    previous_estimate = estimate;
  }
}

TEST(RecoveryEstimate, AMarchIsMarkedOnEachTrianglesWorstTime) {
  // Kept states whose errors sit in different halves of the strip: u_a is the manufactured
  // field on x <= 1 and zero beyond, u_b the reverse at twice the amplitude, with the rest state
  // (a march's t = 0) between them. Each triangle's indicator is the largest of its three, the
  // estimate per state each state's own.
  const Mesh mesh = rectangle(2.0, 1.0, 8, 4);
  Eigen::VectorXd u_a = Eigen::VectorXd::Zero(2 * mesh.num_nodes());
  Eigen::VectorXd u_b = u_a;
  for (int i = 0; i < mesh.num_nodes(); ++i) {
    const Eigen::Vector2d& x = mesh.nodes[i];
    (x.x() <= 1 ? u_a : u_b).segment<2>(2 * i) = (x.x() <= 1 ? 1.0 : 2.0) * exact_u(x);
  }
  const ErrorIndicators a = recovery_indicators(mesh, u_a), b = recovery_indicators(mesh, u_b);
  const MarchIndicators march =
      worst_time_indicators(mesh, {u_a, Eigen::VectorXd::Zero(u_a.size()), u_b});
  ASSERT_EQ(march.estimates.size(), 3u);
  EXPECT_EQ(march.estimates[0], a.estimate);
  EXPECT_EQ(march.estimates[1], 0.0);
  EXPECT_EQ(march.estimates[2], b.estimate);
  int from_a = 0, from_b = 0;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    EXPECT_EQ(march.eta[t], std::max(a.eta[t], b.eta[t])) << "triangle " << t;
    from_a += a.eta[t] > b.eta[t];
    from_b += b.eta[t] > a.eta[t];
  }
  // Both states decide somewhere: neither time is the worst everywhere.
  EXPECT_GT(from_a, 0);
  EXPECT_GT(from_b, 0);
}

} // namespace
} // namespace sig
