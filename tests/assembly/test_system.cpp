// assemble_system from cards: what each load and boundary card puts where, the errors on bad
// references, and the TAE file round trip.
#include "assembly/loads.hpp"
#include "assembly/system.hpp"
#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/error.hpp"
#include "material/mili.hpp"
#include "test_meshes.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace sig {
namespace {

template <class F> InputError input_error(F&& body) {
  try {
    body();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError thrown";
  return InputError("", 0, "", "");
}

LinearSystem assemble(const Mesh& mesh, const std::string& deck) {
  const Datafile datafile = Datafile::parse(deck, "case.dat");
  return assemble_system(mesh, material_table_from_cards(datafile, mesh), datafile);
}

// Sum of the x and y components of a nodal force vector.
Eigen::Vector2d resultant(const Eigen::VectorXd& f) {
  return Eigen::Map<const Eigen::Matrix<double, 2, Eigen::Dynamic>>(f.data(), 2, f.size() / 2)
      .rowwise()
      .sum();
}

TEST(Loads, TractionPressureAndBodyForceResultants) {
  const Mesh mesh = test::square_mesh(4, 3, 2.0, 0.0, 2); // sub-domains split at x = 1
  const std::string materials = "MATERIAL region=1 E=1 nu=0.3\n"
                                "MATERIAL region=2 E=1 nu=0.3 thickness=0.5\n";
  // Traction on the bottom (length 2, half of it in each sub-domain): 1.5 * (2, -1).
  EXPECT_LT((resultant(assemble(mesh, materials + "TRACTION ref=1 f=2,-1\n").f) -
             Eigen::Vector2d(3.0, -1.5))
                .norm(),
            1e-13);
  // Pressure 3 on the right side (length 2, thickness 0.5): -3 * 1 * (1, 0).
  EXPECT_LT(
      (resultant(assemble(mesh, materials + "PRESSURE ref=2 p=3\n").f) - Eigen::Vector2d(-3.0, 0.0))
          .norm(),
      1e-13);
  // A pressure all around a closed boundary has no resultant when the thickness is uniform; with
  // the thinner right half the left side wins by 3 * 2 * (1 - 0.5).
  EXPECT_LT(resultant(assemble(mesh, "MATERIAL E=1 nu=0.3\nPRESSURE ref=1,2,3,4 p=3\n").f).norm(),
            1e-13);
  EXPECT_LT((resultant(assemble(mesh, materials + "PRESSURE ref=1,2,3,4 p=3\n").f) -
             Eigen::Vector2d(3.0, 0.0))
                .norm(),
            1e-13);
  // Body force on sub-domain 2 only (area 2, thickness 0.5), then on both (area 2 + 2 * 0.5).
  EXPECT_LT((resultant(assemble(mesh, materials + "BODYFORCE region=2 f=0,-4\n").f) -
             Eigen::Vector2d(0.0, -4.0))
                .norm(),
            1e-13);
  EXPECT_LT(
      (resultant(assemble(mesh, materials + "BODYFORCE f=1,0\n").f) - Eigen::Vector2d(3.0, 0.0))
          .norm(),
      1e-13);
}

TEST(Loads, OutwardNormalDoesNotDependOnTheEdgeDirection) {
  Mesh mesh = test::square_mesh(2, 2);
  for (BoundaryEdge& e : mesh.edges)
    if (e.ref == 3) std::swap(e.a, e.b); // top edges stored clockwise
  for (const BoundaryEdge& e : mesh.edges) {
    const Eigen::Vector2d n = edge_outward_normal(mesh, e);
    const Eigen::Vector2d expected = e.ref == 1   ? Eigen::Vector2d(0, -1)
                                     : e.ref == 2 ? Eigen::Vector2d(1, 0)
                                     : e.ref == 3 ? Eigen::Vector2d(0, 1)
                                                  : Eigen::Vector2d(-1, 0);
    EXPECT_LT((n - expected).norm(), 1e-15) << "ref " << e.ref;
  }
}

TEST(Dirichlet, OnlyGivenComponentsAreFixedAndLaterCardsWin) {
  const Mesh mesh = test::square_mesh(3, 3);
  const LinearSystem s = assemble(mesh, "MATERIAL E=1 nu=0.3\n"
                                        "DIRICHLET ref=4 ux=0.5\n"
                                        "DIRICHLET ref=5 ux=-1 uy=2\n");
  // Left side: 4 nodes, u1 only; vertex (0, 0) = node 0 gets both, its u1 from the later card.
  ASSERT_EQ(s.dirichlet_dofs.size(), 5u);
  EXPECT_EQ(s.dirichlet_dofs[0], 0);
  EXPECT_EQ(s.dirichlet_values(0), -1.0);
  EXPECT_EQ(s.dirichlet_dofs[1], 1);
  EXPECT_EQ(s.dirichlet_values(1), 2.0);
  for (std::size_t k = 2; k < 5; ++k) {
    EXPECT_EQ(s.dirichlet_dofs[k] % 2, 0);
    EXPECT_EQ(s.dirichlet_values(static_cast<int>(k)), 0.5);
    EXPECT_EQ(mesh.nodes[s.dirichlet_dofs[k] / 2].x(), 0.0);
  }
}

TEST(Dirichlet, UnknownReferenceIsAnInputErrorOnItsLine) {
  const Mesh mesh = test::square_mesh(2, 2);
  const InputError e = input_error(
      [&] { assemble(mesh, "MATERIAL E=1 nu=0.3\n# clamp\nDIRICHLET ref=7 ux=0 uy=0\n"); });
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.field(), "ref");
  EXPECT_EQ(e.file(), "case.dat");
  EXPECT_NE(std::string(e.what()).find("reference 7 is on no edge or vertex of the mesh; "
                                       "references present: 1 2 3 4 5"),
            std::string::npos)
      << e.what();
  // Reference 5 is only a vertex: a traction needs edges.
  const InputError t =
      input_error([&] { assemble(mesh, "MATERIAL E=1 nu=0.3\nTRACTION ref=5 f=1,0\n"); });
  EXPECT_EQ(t.line(), 2);
  EXPECT_EQ(t.field(), "ref");
  const InputError r =
      input_error([&] { assemble(mesh, "MATERIAL E=1 nu=0.3\nBODYFORCE region=3 f=1,0\n"); });
  EXPECT_EQ(r.field(), "region");
}

TEST(Tae, RoundTrip) {
  const Mesh mesh = test::square_mesh(3, 2, 1.0, 0.2, 2);
  const LinearSystem s = assemble(mesh, "MATERIAL region=1 E=2 nu=0.3 rho=3\n"
                                        "MATERIAL region=2 E=5 nu=0.2 rho=1 plane=stress\n"
                                        "TRACTION ref=2 f=1,-1\n"
                                        "BODYFORCE f=0,-9.81\n"
                                        "DIRICHLET ref=4 ux=0 uy=0.125\n");
  ASSERT_GT(s.M.nonZeros(), 0);
  const auto path = std::filesystem::temp_directory_path() /
                    ("sig_test_tae_" + std::to_string(::getpid()) + ".tae");
  write_tae(path, s, "round trip");
  const LinearSystem back = read_tae(path);
  // The file holds 1-based CSR, as a Fortran reader wants it.
  const Ds ds = read_ds(path, "TAE");
  std::filesystem::remove(path);
  EXPECT_EQ(ds.ints("K_rowptr").front(), 1);
  EXPECT_EQ(ds.ints("dirichlet_dof").front(), s.dirichlet_dofs.front() + 1);
  EXPECT_EQ(ds.integer("ndof"), s.num_dofs());

  EXPECT_EQ(back.num_dofs(), s.num_dofs());
  EXPECT_EQ((back.K - s.K).norm(), 0.0);
  EXPECT_EQ((back.M - s.M).norm(), 0.0);
  EXPECT_EQ(back.K.nonZeros(), s.K.nonZeros());
  EXPECT_EQ(back.M_lumped, s.M_lumped);
  EXPECT_EQ(back.f, s.f);
  EXPECT_EQ(back.dirichlet_dofs, s.dirichlet_dofs);
  EXPECT_EQ(back.dirichlet_values, s.dirichlet_values);
}

TEST(Tae, NoMassWithoutDensity) {
  const Mesh mesh = test::square_mesh(2, 2);
  const LinearSystem s = assemble(mesh, "MATERIAL E=1 nu=0.3\n");
  EXPECT_EQ(s.M.size(), 0);
  EXPECT_EQ(s.M_lumped.size(), s.num_dofs());
  EXPECT_EQ(s.M_lumped.norm(), 0.0);
  const auto path = std::filesystem::temp_directory_path() /
                    ("sig_test_tae_nomass_" + std::to_string(::getpid()) + ".tae");
  write_tae(path, s, "no mass");
  const LinearSystem back = read_tae(path);
  std::filesystem::remove(path);
  EXPECT_EQ(back.M.size(), 0);
  EXPECT_EQ((back.K - s.K).norm(), 0.0);
}

} // namespace
} // namespace sig
