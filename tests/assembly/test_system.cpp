// assemble_system from cards: what each load and boundary card puts where, the errors on bad
// references, and the TAE file round trip.
#include "assembly/loads.hpp"
#include "assembly/system.hpp"
#include "assembly/tae_parts.hpp"
#include "core/datafile.hpp"
#include "core/ds.hpp"
#include "core/ds_stream.hpp"
#include "core/error.hpp"
#include "input_error.hpp"
#include "material/mili.hpp"
#include "scratch_folder.hpp"
#include "test_meshes.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

namespace sig {
namespace {

using testing::input_error;

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

// ramp=t1 puts g / t1 into the rate and nothing into the load at t = 0: f(t) = f + t rate.
TEST(Loads, RampedLoadsGoToTheRate) {
  const Mesh mesh = test::square_mesh(4, 3, 2.0, 0.0, 2);
  const std::string material = "MATERIAL E=1 nu=0.3\n";
  const LinearSystem constant = assemble(mesh, material + "TRACTION ref=1 f=2,-1\n"
                                                          "PRESSURE ref=2 p=3\n"
                                                          "BODYFORCE f=0,-4\n");
  const LinearSystem ramped = assemble(mesh, material + "TRACTION ref=1 f=2,-1 ramp=0.5\n"
                                                        "PRESSURE ref=2 p=3 ramp=2\n"
                                                        "BODYFORCE f=0,-4\n");
  const LinearSystem traction = assemble(mesh, material + "TRACTION ref=1 f=2,-1\n");
  const LinearSystem pressure = assemble(mesh, material + "PRESSURE ref=2 p=3\n");
  const LinearSystem body = assemble(mesh, material + "BODYFORCE f=0,-4\n");
  EXPECT_TRUE(constant.time_loads.empty());
  ASSERT_FALSE(ramped.time_loads.empty());
  EXPECT_LT((ramped.f - body.f).norm(), 1e-14); // f is the load at t = 0
  const Eigen::VectorXd rate = traction.f / 0.5 + pressure.f / 2;
  EXPECT_LT((ramped.time_loads.rate - rate).norm(), 1e-13);
  EXPECT_LT((ramped.load_at(0.75) - (body.f + 0.75 * rate)).norm(), 1e-13);
  EXPECT_LT((constant.f - (traction.f + pressure.f + body.f)).norm(), 1e-13);
  for (const char* bad :
       {"TRACTION ref=1 f=2,-1 ramp=0", "PRESSURE ref=2 p=3 ramp=-1", "BODYFORCE f=0,-4 ramp=0"}) {
    const InputError e = input_error([&] { assemble(mesh, material + bad + "\n"); });
    EXPECT_EQ(e.line(), 2) << bad;
    EXPECT_EQ(e.field(), "ramp") << bad;
  }
  const Datafile deck =
      Datafile::parse(material + "TRACTION ref=1 f=1,0\nBODYFORCE f=0,-1 ramp=1\n", "case.dat");
  ASSERT_NE(ramped_load_card(deck), nullptr);
  EXPECT_EQ(ramped_load_card(deck)->line, 3);
  EXPECT_EQ(ramped_load_card(Datafile::parse(material, "case.dat")), nullptr);
}

// The viscosity A (eta1, eta2) is Hooke's operator with the "Lame" constants (eta1, eta2 / 2): its
// matrix equals the stiffness of the Hooke law with those constants; a memory term's matrix is its
// tensor's stiffness, terms of one beta summed, on its sub-domains only.
TEST(ViscoelasticSystem, ViscosityAndMemoryMatrices) {
  const Mesh mesh = test::square_mesh(3, 3, 1.0, 0.2, 2);
  const double E = 100, nu = 0.3;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  std::ostringstream deck;
  deck.precision(17);
  deck << "MATERIAL law=kelvin-voigt E=7 nu=0.2 eta1=" << lambda << " eta2=" << 2 * mu << "\n"
       << "MEMORY region=2 E=20 nu=0.3 beta=10\nMEMORY region=2 E=5 nu=0.3 beta=10\n"
       << "MEMORY E=3 nu=0.1 beta=2\n";
  const LinearSystem kv = assemble(mesh, deck.str());
  const LinearSystem hooke = assemble(mesh, "MATERIAL E=100 nu=0.3\n");
  EXPECT_LT((kv.V - hooke.K).norm(), 1e-12 * hooke.K.norm());
  EXPECT_LT((kv.K - assemble(mesh, "MATERIAL E=7 nu=0.2\n").K).norm(), 1e-12 * kv.K.norm());
  // In the order the table meets them: sub-domain 1 has only beta = 2.
  ASSERT_EQ(kv.memory.size(), 2u);
  EXPECT_EQ(kv.memory[0].beta, 2);
  EXPECT_EQ(kv.memory[1].beta, 10);
  const LinearSystem right = assemble(mesh, "MATERIAL region=1 E=1e-30 nu=0.3\n"
                                            "MATERIAL region=2 E=25 nu=0.3\n");
  EXPECT_LT((kv.memory[1].K - right.K).norm(), 1e-12 * right.K.norm());
  EXPECT_LT((kv.memory[0].K - assemble(mesh, "MATERIAL E=3 nu=0.1\n").K).norm(), 1e-12);
  const LinearSystem plain = assemble(mesh, "MATERIAL E=1 nu=0.3\n");
  EXPECT_EQ(plain.V.size(), 0);
  EXPECT_TRUE(plain.memory.empty());
}

TEST(Loads, OutwardNormalDoesNotDependOnTheEdgeDirection) {
  Mesh mesh = test::square_mesh(2, 2);
  for (Facet& e : mesh.facets)
    if (e.ref == 3) std::swap(e.node[0], e.node[1]); // top edges stored clockwise
  for (const Facet& e : mesh.facets) {
    const Eigen::Vector2d n = edge_outward_normal(mesh, e);
    const Eigen::Vector2d expected = e.ref == 1   ? Eigen::Vector2d(0, -1)
                                     : e.ref == 2 ? Eigen::Vector2d(1, 0)
                                     : e.ref == 3 ? Eigen::Vector2d(0, 1)
                                                  : Eigen::Vector2d(-1, 0);
    EXPECT_LT((n - expected).norm(), 1e-15) << "ref " << e.ref;
  }
}

TEST(Dirichlet, OnlyGivenComponentsAreFixedAndTwoValuesForOneDofAreRefused) {
  const Mesh mesh = test::square_mesh(3, 3);
  const LinearSystem s = assemble(mesh, "MATERIAL E=1 nu=0.3\n"
                                        "DIRICHLET ref=4 ux=0.5\n"
                                        "DIRICHLET ref=5 ux=0.5 uy=2\n");
  // Left side: 4 nodes, u1 only; vertex (0, 0) = node 0 gets both, its u1 from both cards.
  ASSERT_EQ(s.dirichlet_dofs.size(), 5u);
  EXPECT_EQ(s.dirichlet_dofs[0], 0);
  EXPECT_EQ(s.dirichlet_values(0), 0.5);
  EXPECT_EQ(s.dirichlet_dofs[1], 1);
  EXPECT_EQ(s.dirichlet_values(1), 2.0);
  for (std::size_t k = 2; k < 5; ++k) {
    EXPECT_EQ(s.dirichlet_dofs[k] % 2, 0);
    EXPECT_EQ(s.dirichlet_values(static_cast<int>(k)), 0.5);
    EXPECT_EQ(mesh.nodes[s.dirichlet_dofs[k] / 2].x(), 0.0);
  }
  // The later card used to win silently: u1 of (0, 0) cannot be 0.5 and -1.
  const InputError e = input_error([&] {
    assemble(mesh, "MATERIAL E=1 nu=0.3\nDIRICHLET ref=4 ux=0.5\nDIRICHLET ref=5 ux=-1 uy=2\n");
  });
  EXPECT_EQ(e.line(), 3);
  EXPECT_EQ(e.field(), "ux");
  EXPECT_NE(std::string(e.what()).find("gives node 1 (at (0, 0), reference 5) ux = -1, but the "
                                       "DIRICHLET card of line 2 gives it 0.5"),
            std::string::npos)
      << e.what();
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
  const testing::ScratchFolder dir;
  const auto path = dir / "case.tae";
  write_tae(path, s, "round trip");
  const LinearSystem back = read_tae(path);
  // The file holds 1-based CSR, as a Fortran reader wants it.
  const Ds ds = read_ds(path, "TAE");
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
  EXPECT_EQ(back.V.size(), 0);
  EXPECT_TRUE(back.memory.empty());
  EXPECT_TRUE(back.time_loads.empty());
}

/// A Kelvin-Voigt body with two memory terms, a ramped and a constant traction (and `density`,
/// e.g. " rho=3", for a mass) on a mesh of two regions.
LinearSystem viscoelastic_system(const Mesh& mesh, const std::string& density = "") {
  return assemble(mesh, "MATERIAL law=kelvin-voigt E=2 nu=0.3 eta1=0.25 eta2=0.5" + density +
                            "\nMEMORY region=1 E=1 nu=0.3 beta=10\nMEMORY E=3 nu=0.2 beta=0.5\n"
                            "TRACTION ref=3 f=0,-10 ramp=1\nTRACTION ref=2 f=1,0\n"
                            "DIRICHLET ref=4 ux=0 uy=0\n");
}

TEST(Tae, ViscoelasticRoundTrip) {
  const Mesh mesh = test::square_mesh(3, 2, 1.0, 0.2, 2);
  const LinearSystem s = viscoelastic_system(mesh);
  const testing::ScratchFolder dir;
  const auto path = dir / "case.tae";
  write_tae(path, s, "viscoelastic round trip");
  const LinearSystem back = read_tae(path);
  EXPECT_EQ((back.V - s.V).norm(), 0.0);
  ASSERT_EQ(back.memory.size(), 2u);
  for (std::size_t j = 0; j < 2; ++j) {
    EXPECT_EQ(back.memory[j].beta, s.memory[j].beta);
    EXPECT_EQ((back.memory[j].K - s.memory[j].K).norm(), 0.0);
  }
  EXPECT_EQ(back.time_loads.rate, s.time_loads.rate);
  EXPECT_EQ(back.f, s.f);
  EXPECT_EQ(back.load_at(0.5), s.load_at(0.5));
  EXPECT_GT(s.time_loads.rate.norm(), 0);
}

// Two ranks' rows (mpirun sig-solve): read streaming, in pieces (K_col and K_val of this mesh
// exceed one), each rank's K and f hold its rows, on a symmetric pattern, and sum to the whole.
TEST(Tae, RowsOfTwoRanksSumToTheWhole) {
  const Mesh mesh = test::square_mesh(80, 80);
  const LinearSystem s = assemble(mesh, "MATERIAL E=2 nu=0.3\nTRACTION ref=2 f=1,-1\n"
                                        "DIRICHLET ref=4 ux=0 uy=0.125\n");
  ASSERT_GT(s.K.nonZeros() * sizeof(double), kDsPieceBytes);
  const testing::ScratchFolder dir;
  const auto path = dir / "case.tae";
  write_tae(path, s, "rows");
  const int n = s.num_dofs();
  std::vector<char> first(static_cast<std::size_t>(n)), second(first.size());
  for (int dof = 0; dof < n; ++dof) // whole nodes, as rows_of_rank gives them
    first[static_cast<std::size_t>(dof)] = dof / 2 % 3 == 0;
  for (std::size_t k = 0; k < first.size(); ++k)
    second[k] = !first[k];
  const LinearSystem a = read_tae_rows(path, first), b = read_tae_rows(path, second);
  EXPECT_TRUE(a.rank_rows && b.rank_rows);
  EXPECT_EQ((a.K + b.K - s.K).norm(), 0.0);
  EXPECT_EQ(a.f + b.f, s.f);
  for (const auto& [part, owned] : {std::pair{&a, &first}, std::pair{&b, &second}}) {
    EXPECT_EQ(part->dirichlet_dofs, s.dirichlet_dofs);
    EXPECT_EQ(part->dirichlet_values, s.dirichlet_values);
    for (int j = 0; j < n; ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(part->K, j); it; ++it)
        EXPECT_TRUE((*owned)[static_cast<std::size_t>(it.row())] || it.value() == 0.0);
    Eigen::SparseMatrix<double> pattern = part->K; // the stored places, explicit zeros too
    pattern.coeffs().setOnes();
    EXPECT_EQ((pattern - Eigen::SparseMatrix<double>(pattern.transpose())).norm(), 0.0);
    EXPECT_LT(pattern.nonZeros(), s.K.nonZeros()); // not the whole matrix
  }
  // A partition of another mesh is refused with the file named.
  EXPECT_THROW(read_tae_rows(path, std::vector<char>(first.size() - 2, 1)), Error);
}

// A march's rows (mpirun sig-march): M, V, every memory term and M_lumped of each rank's rows sum
// to the whole, as K; the time loads come whole to every rank; without `march` none of them.
TEST(Tae, MarchRowsOfTwoRanksSumToTheWhole) {
  const Mesh mesh = test::square_mesh(6, 4, 1.0, 0.2, 2);
  const LinearSystem s = viscoelastic_system(mesh, " rho=3");
  ASSERT_EQ(s.memory.size(), 2u);
  ASSERT_GT(s.M.nonZeros(), 0);
  const testing::ScratchFolder dir;
  const auto path = dir / "case.tae";
  write_tae(path, s, "march rows");
  const int n = s.num_dofs();
  std::vector<char> first(static_cast<std::size_t>(n)), second(first.size());
  for (int dof = 0; dof < n; ++dof)
    first[static_cast<std::size_t>(dof)] = dof / 2 % 2 == 0;
  for (std::size_t k = 0; k < first.size(); ++k)
    second[k] = !first[k];
  const LinearSystem a = read_tae_rows(path, first, true), b = read_tae_rows(path, second, true);
  EXPECT_EQ((a.K + b.K - s.K).norm(), 0.0);
  EXPECT_EQ((a.M + b.M - s.M).norm(), 0.0);
  EXPECT_EQ((a.V + b.V - s.V).norm(), 0.0);
  EXPECT_EQ(a.M_lumped + b.M_lumped, s.M_lumped);
  EXPECT_EQ(a.f + b.f, s.f);
  for (std::size_t j = 0; j < 2; ++j) {
    EXPECT_EQ(a.memory[j].beta, s.memory[j].beta);
    EXPECT_EQ((a.memory[j].K + b.memory[j].K - s.memory[j].K).norm(), 0.0);
    EXPECT_GT(a.memory[j].K.norm(), 0.0);
    EXPECT_GT(b.memory[j].K.norm(), 0.0);
  }
  for (const LinearSystem* part : {&a, &b}) {
    EXPECT_EQ(part->time_loads.rate, s.time_loads.rate);
    for (int j = 0; j < n; ++j)
      for (Eigen::SparseMatrix<double>::InnerIterator it(part->M, j); it; ++it)
        EXPECT_TRUE((part == &a ? first : second)[static_cast<std::size_t>(it.row())]);
  }
  const LinearSystem solve = read_tae_rows(path, first);
  EXPECT_EQ(solve.M.size(), 0);
  EXPECT_EQ(solve.V.size(), 0);
  EXPECT_TRUE(solve.memory.empty() && solve.time_loads.empty());
}

// Whether `body` throws a sig::Error whose message holds `text`.
template <class F> void error_containing(F&& body, const std::string& text) {
  try {
    body();
    ADD_FAILURE() << "no error; expected one saying '" << text << "'";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

// A distributed assembly (mpirun sig-assemble): each rank assembles its rows on the cells that
// reach them and writes its part; a rank of the solve or the march reads from its part what it
// would stream off the whole TAE, bit for bit. The index holds the whole body's vectors, and a
// reader refuses a job of another size, a part of another run or rank and a missing part.
TEST(TaeParts, EachRankReadsOfItsPartWhatTheWholeTaeGives) {
  const Mesh mesh = test::square_mesh(6, 4, 1.0, 0.2, 2);
  const std::string deck = "MATERIAL law=kelvin-voigt E=2 nu=0.3 eta1=0.25 eta2=0.5 rho=3\n"
                           "MEMORY region=1 E=1 nu=0.3 beta=10\nMEMORY E=3 nu=0.2 beta=0.5\n"
                           "TRACTION ref=3 f=0,-10 ramp=1\nTRACTION ref=2 f=1,0\n"
                           "BODYFORCE f=0.5,-2\nDIRICHLET ref=4 ux=0 uy=0\n";
  const Datafile datafile = Datafile::parse(deck, "case.dat");
  const MaterialTable table = material_table_from_cards(datafile, mesh);
  const LinearSystem s = assemble_system(mesh, table, datafile);
  const testing::ScratchFolder dir;
  std::filesystem::create_directories(dir / "whole");
  std::filesystem::create_directories(dir / "parts");
  const auto whole = dir / "whole" / "case.tae", index = dir / "parts" / "case.tae";
  write_tae(whole, s, "whole");
  const int n = s.num_dofs();
  std::vector<std::vector<char>> owned(2, std::vector<char>(static_cast<std::size_t>(n)));
  for (int dof = 0; dof < n; ++dof) // whole nodes, as rows_of_rank gives them
    owned[dof / 2 % 3 == 0][static_cast<std::size_t>(dof)] = 1;
  const TaeParts parts{2, "0123abcd"};
  for (int rank = 0; rank < 2; ++rank) {
    const LinearSystem rows = assemble_system(mesh, table, datafile, &owned[rank]);
    EXPECT_LT(rows.K.nonZeros(), s.K.nonZeros());
    write_tae_part(index, rank, parts, rows, "part");
  }
  write_tae_index(index, parts, s, "index");
  for (const bool march : {false, true})
    for (int rank = 0; rank < 2; ++rank) {
      const LinearSystem a = read_tae_part(index, parts, rank, 2, owned[rank], march);
      const LinearSystem b = read_tae_rows(whole, owned[rank], march);
      EXPECT_TRUE(a.rank_rows);
      for (const auto& [x, y] : {std::pair{&a.K, &b.K}, {&a.M, &b.M}, {&a.V, &b.V}}) {
        EXPECT_EQ(x->rows(), y->rows());
        EXPECT_EQ(x->nonZeros(), y->nonZeros());
        if (x->size() > 0) EXPECT_EQ((*x - *y).norm(), 0.0); // a solve reads no M, V: 0 x 0
      }
      ASSERT_EQ(a.memory.size(), b.memory.size());
      for (std::size_t j = 0; j < a.memory.size(); ++j)
        EXPECT_EQ((a.memory[j].K - b.memory[j].K).norm(), 0.0);
      EXPECT_EQ(a.f, b.f);
      EXPECT_EQ(a.M_lumped, b.M_lumped);
      EXPECT_EQ(a.time_loads.rate, b.time_loads.rate);
      EXPECT_EQ(a.dirichlet_dofs, b.dirichlet_dofs);
    }
  // The index: the parts, the whole body's loads; no matrix for a process alone.
  ASSERT_TRUE(read_tae_index(index).has_value());
  EXPECT_EQ(read_tae_index(index)->run, parts.run);
  EXPECT_FALSE(read_tae_index(whole).has_value());
  EXPECT_EQ(read_ds(index, "TAE").reals("f"), read_ds(whole, "TAE").reals("f"));
  error_containing([&] { read_tae(index); }, "mpirun -np 2");
  // Mismatches, each naming the file.
  error_containing([&] { read_tae_part(index, parts, 0, 3, owned[0], false); }, "this job has 3");
  error_containing(
      [&] {
        read_tae_part(index, TaeParts{2, "other"}, 0, 2, owned[0], false);
      },
      "a part of another run");
  error_containing([&] { read_tae_part(index, parts, 0, 2, owned[1], false); },
                   "not this rank's rows");
  std::filesystem::copy_file(tae_part_path(index, 1), tae_part_path(index, 0),
                             std::filesystem::copy_options::overwrite_existing);
  error_containing([&] { read_tae_part(index, parts, 0, 2, owned[0], false); },
                   "the part of rank 1 of 2");
  remove_tae_parts(index, 1);
  EXPECT_TRUE(std::filesystem::exists(tae_part_path(index, 0)));
  error_containing([&] { read_tae_part(index, parts, 1, 2, owned[1], false); },
                   "case.tae.r1: missing");
}

TEST(Tae, NoMassWithoutDensity) {
  const Mesh mesh = test::square_mesh(2, 2);
  const LinearSystem s = assemble(mesh, "MATERIAL E=1 nu=0.3\n");
  EXPECT_EQ(s.M.size(), 0);
  EXPECT_EQ(s.M_lumped.size(), s.num_dofs());
  EXPECT_EQ(s.M_lumped.norm(), 0.0);
  const testing::ScratchFolder dir;
  const auto path = dir / "case.tae";
  write_tae(path, s, "no mass");
  const LinearSystem back = read_tae(path);
  EXPECT_EQ(back.M.size(), 0);
  EXPECT_EQ((back.K - s.K).norm(), 0.0);
}

} // namespace
} // namespace sig
