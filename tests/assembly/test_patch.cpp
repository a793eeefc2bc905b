// Patch tests: P1 elements reproduce any linear displacement (constant strain) exactly, whether
// it is imposed on the whole boundary or produced by the matching constant tractions.
#include "assembly/dirichlet.hpp"
#include "assembly/strain.hpp"
#include "assembly/system.hpp"
#include "core/datafile.hpp"
#include "material/mili.hpp"
#include "test_meshes.hpp"

#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include <set>
#include <sstream>

namespace sig {
namespace {

MaterialTable one_material(double E, double nu, PlaneMode plane) {
  MaterialTable table;
  table.entries.resize(1);
  table.entries[0].hooke = {E, nu, plane};
  return table;
}

Eigen::VectorXd solve(const LinearSystem& system) {
  const ReducedSystem reduced = reduce(system);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(reduced.K);
  EXPECT_EQ(ldlt.info(), Eigen::Success);
  return reduced.expand(ldlt.solve(reduced.f));
}

TEST(PatchTest, LinearDisplacementOnTheBoundaryIsReproducedInside) {
  const Mesh mesh = test::square_mesh(6, 5, 1.0, 0.3);
  Eigen::Matrix2d A;
  A << 1e-3, -4e-4, 7e-4, -2e-3;
  const Eigen::Vector2d b(3e-4, -1e-4);
  std::set<int> boundary;
  for (const Facet& e : mesh.facets)
    boundary.insert({e.node[0], e.node[1]});
  for (PlaneMode plane : {PlaneMode::strain, PlaneMode::stress}) {
    const MaterialTable table = one_material(200.0, 0.3, plane);
    LinearSystem system;
    system.K = assemble_stiffness(mesh, table, SparsityPattern(mesh));
    system.f = Eigen::VectorXd::Zero(system.K.rows());
    system.dirichlet_values.resize(2 * static_cast<int>(boundary.size()));
    for (int node : boundary)
      for (int c = 0; c < 2; ++c) {
        system.dirichlet_values(static_cast<int>(system.dirichlet_dofs.size())) =
            (A * mesh.nodes[node] + b)(c);
        system.dirichlet_dofs.push_back(2 * node + c);
      }
    const Eigen::VectorXd u = solve(system);
    int interior = 0;
    for (int node = 0; node < mesh.num_nodes(); ++node) {
      if (boundary.count(node)) continue;
      ++interior;
      const Eigen::Vector2d exact = A * mesh.nodes[node] + b;
      EXPECT_LT((u.segment<2>(2 * node) - exact).norm(), 1e-12 * exact.norm()) << "node " << node;
    }
    EXPECT_EQ(interior, 5 * 4);
    const Eigen::Vector3d eps(A(0, 0), A(1, 1), A(0, 1) + A(1, 0));
    for (const Eigen::Vector3d& e : element_strains(mesh, u))
      EXPECT_LT((e - eps).norm(), 1e-12);
  }
}

// Constant stress sigma on the unit square: tractions sigma n on the bottom, right and top
// sides, and on the left side a roller (u1 = 0) with the tangential traction -s12; the vertex
// (0, 0) is fixed vertically. The exact displacement is u1 = e11 x, u2 = 2 e12 x + e22 y.
TEST(PatchTest, ConstantTractionsGiveTheConstantStrain) {
  const Mesh mesh = test::square_mesh(5, 6, 1.0, 0.3);
  const double E = 70.0, nu = 0.25;
  const Eigen::Vector3d sigma(1.5, -0.75, 0.5);
  const Eigen::Vector3d eps = Hooke{E, nu, PlaneMode::strain}.D().inverse() * sigma;
  std::ostringstream deck;
  deck << "MATERIAL law=hooke E=" << E << " nu=" << nu << "\n"
       << "TRACTION ref=1 f=" << -sigma(2) << "," << -sigma(1) << "\n"
       << "TRACTION ref=2 f=" << sigma(0) << "," << sigma(2) << "\n"
       << "TRACTION ref=3 f=" << sigma(2) << "," << sigma(1) << "\n"
       << "TRACTION ref=4 f=" << -sigma(0) << "," << -sigma(2) << "\n"
       << "DIRICHLET ref=4 ux=0\n"
       << "DIRICHLET ref=5 uy=0\n";
  const Datafile datafile = Datafile::parse(deck.str(), "patch.dat");
  const MaterialTable table = material_table_from_cards(datafile, mesh);
  const LinearSystem system = assemble_system(mesh, table, datafile);
  EXPECT_EQ(system.dirichlet_dofs.size(), 7u + 1u); // u1 on the 7 left nodes, u2 at (0, 0)
  const Eigen::VectorXd u = solve(system);
  for (int node = 0; node < mesh.num_nodes(); ++node) {
    const Eigen::Vector2d x = mesh.nodes[node];
    const Eigen::Vector2d exact(eps(0) * x.x(), eps(2) * x.x() + eps(1) * x.y());
    EXPECT_LT((u.segment<2>(2 * node) - exact).norm(), 1e-12 * eps.norm()) << "node " << node;
  }
  for (const Eigen::Vector3d& s : element_stresses(mesh, table, u))
    EXPECT_LT((s - sigma).norm(), 1e-11 * sigma.norm());
}

} // namespace
} // namespace sig
