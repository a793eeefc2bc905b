// The precomputed pattern and scatter map give the same matrix as a plain triplet assembly, and
// the elimination of Dirichlet dofs keeps exactly the free rows and columns.
#include "assembly/dirichlet.hpp"
#include "assembly/p1.hpp"
#include "assembly/pattern.hpp"
#include "assembly/system.hpp"
#include "material/mili.hpp"
#include "test_meshes.hpp"

#include <gtest/gtest.h>

#include <set>
#include <utility>

namespace sig {
namespace {

MaterialTable two_materials() {
  MaterialTable table;
  SubdomainMaterial soft, hard;
  soft.subdomain = 1;
  soft.hooke = {1.0, 0.3, PlaneMode::strain};
  soft.density = 2.0;
  hard.subdomain = 2;
  hard.hooke = {50.0, 0.2, PlaneMode::stress};
  hard.thickness = 0.5;
  hard.density = 1.0;
  table.entries = {soft, hard};
  return table;
}

TEST(Pattern, HasOneBlockPerPairOfNeighbouringNodesWithSortedIndices) {
  const Mesh mesh = test::square_mesh(5, 4, 1.0, 0.2);
  const SparsityPattern pattern(mesh);
  std::set<std::pair<int, int>> edges;
  for (const auto& t : mesh.cells)
    for (int i = 0; i < 3; ++i)
      edges.insert(std::minmax(t[i], t[(i + 1) % 3]));
  // Each node couples with itself and each neighbour: 2 x 2 entries per ordered pair.
  EXPECT_EQ(pattern.nnz(), 4 * (mesh.num_nodes() + 2 * static_cast<int>(edges.size())));
  EXPECT_EQ(pattern.num_dofs(), 2 * mesh.num_nodes());
  for (int col = 0; col < pattern.num_dofs(); ++col)
    for (int p = pattern.outer()[col] + 1; p < pattern.outer()[col + 1]; ++p)
      EXPECT_LT(pattern.inner()[p - 1], pattern.inner()[p]);
}

TEST(Pattern, ScatterAssemblyEqualsTripletAssembly) {
  const Mesh mesh = test::square_mesh(6, 5, 2.0, 0.25, 2);
  const MaterialTable table = two_materials();
  const SparsityPattern pattern(mesh);
  const Eigen::SparseMatrix<double> K = assemble_stiffness(mesh, table, pattern);

  std::vector<Eigen::Triplet<double>> triplets;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const SubdomainMaterial& m = table.of(mesh.subdomain[t]);
    const Matrix6d ke = p1_stiffness(triangle_vertices(mesh, t), m.hooke.D(), m.thickness);
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        triplets.emplace_back(2 * mesh.cells[t][i / 2] + i % 2, 2 * mesh.cells[t][j / 2] + j % 2,
                              ke(i, j));
  }
  Eigen::SparseMatrix<double> reference(K.rows(), K.cols());
  reference.setFromTriplets(triplets.begin(), triplets.end());
  EXPECT_LT((K - reference).norm(), 1e-14 * reference.norm());
  const Eigen::SparseMatrix<double> Kt = K.transpose();
  EXPECT_LT((K - Kt).norm(), 1e-14 * K.norm());
}

TEST(Pattern, MassMatchesLumpedRowSumsAndTotalMass) {
  const Mesh mesh = test::square_mesh(4, 4, 2.0, 0.2, 2);
  const MaterialTable table = two_materials();
  const SparsityPattern pattern(mesh);
  const Eigen::SparseMatrix<double> M = assemble_mass(mesh, table, pattern);
  const Eigen::VectorXd lumped = assemble_lumped_mass(mesh, table);
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(M.rows());
  EXPECT_LT((M * ones - lumped).norm(), 1e-14);
  double total = 0.0;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const SubdomainMaterial& m = table.of(mesh.subdomain[t]);
    total += m.density * m.thickness * p1_area(triangle_vertices(mesh, t));
  }
  EXPECT_NEAR(lumped.sum(), 2 * total, 1e-13); // two components
}

TEST(Dirichlet, ReduceKeepsFreeRowsAndMovesImposedValuesToTheRightSide) {
  const Mesh mesh = test::square_mesh(3, 3, 1.0, 0.1);
  MaterialTable table;
  table.entries.resize(1);
  const SparsityPattern pattern(mesh);
  LinearSystem system;
  system.K = assemble_stiffness(mesh, table, pattern);
  system.f = Eigen::VectorXd::LinSpaced(system.K.rows(), -1.0, 2.0);
  system.dirichlet_dofs = {0, 3, 7, 30};
  system.dirichlet_values = Eigen::Vector4d(0.5, -1.0, 2.0, 0.25);
  const ReducedSystem r = reduce(system);
  ASSERT_EQ(r.num_free(), system.num_dofs() - 4);
  const Eigen::MatrixXd K = system.K;
  const Eigen::MatrixXd Kr = r.K;
  for (int i = 0; i < r.num_free(); ++i)
    for (int j = 0; j < r.num_free(); ++j)
      ASSERT_EQ(Kr(i, j), K(r.free_dofs[i], r.free_dofs[j]));
  // With u = expand(v), the free rows of K u - f equal K_ff v - f_r.
  const Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(r.num_free(), 0.3, -0.8);
  const Eigen::VectorXd u = r.expand(v);
  EXPECT_EQ(u(3), -1.0);
  EXPECT_EQ(u(30), 0.25);
  EXPECT_LT((r.restrict(system.K * u - system.f) - (r.K * v - r.f)).norm(), 1e-12);
  EXPECT_EQ(r.restrict(u), v);
  EXPECT_EQ(r.reduced_index[3], -1);
  EXPECT_EQ(r.reduced_index[r.free_dofs[5]], 5);
}

} // namespace
} // namespace sig
