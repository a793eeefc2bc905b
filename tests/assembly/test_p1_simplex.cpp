// The P1 simplex routine (assembly/p1_simplex.hpp) in 2D and 3D: the patch test on unstructured
// meshes (a linear displacement imposed on the boundary is reproduced exactly inside, with its
// constant stress), the rigid motions in the kernel, the 2D kernels as its d = 2 case.
#include "assembly/p1.hpp"
#include "assembly/p1_simplex.hpp"
#include "material/hooke.hpp"
#include "mesh/gmsh.hpp"
#include "mesh/mesh.hpp"
#include "test_bodies.hpp"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

namespace sig {
namespace {

template <int d> VoigtMatrix<d> elasticity(const Hooke& law) {
  if constexpr (d == 2)
    return law.D();
  else
    return law.D3();
}

/// The Voigt strain (engineering shear) of the displacement gradient A.
template <int d>
Eigen::Matrix<double, voigt_size(d), 1> voigt_strain(const Eigen::Matrix<double, d, d>& A) {
  Eigen::Matrix<double, voigt_size(d), 1> eps;
  for (int k = 0; k < d; ++k)
    eps(k) = A(k, k);
  constexpr auto shears = voigt_shears<d>();
  for (int s = 0; s < voigt_size(d) - d; ++s)
    eps(d + s) = A(shears[s].first, shears[s].second) + A(shears[s].second, shears[s].first);
  return eps;
}

/// Assemble K over the mesh, impose u = A x + c on the nodes of the referenced facets, solve for
/// the others: they must carry A x + c, and every cell the strain of A.
template <int d> void patch_test(const Mesh& mesh) {
  ASSERT_EQ(mesh.dim, d);
  Hooke law;
  law.E = 210;
  law.nu = 0.3;
  const VoigtMatrix<d> D = elasticity<d>(law);
  Eigen::Matrix<double, d, d> A;
  A.setRandom();
  A *= 1e-3;
  const Eigen::Matrix<double, d, 1> c = Eigen::Matrix<double, d, 1>::LinSpaced(0.1, 0.2);
  const int n = d * mesh.num_nodes();
  std::vector<Eigen::Triplet<double>> entries;
  for (int t = 0; t < mesh.num_cells(); ++t) {
    const SimplexMatrix<d> ke = p1_simplex_stiffness<d>(simplex_vertices<d>(mesh, t), D, 1.0);
    for (int i = 0; i < d * (d + 1); ++i)
      for (int j = 0; j < d * (d + 1); ++j)
        entries.emplace_back(d * mesh.cells[t][i / d] + i % d, d * mesh.cells[t][j / d] + j % d,
                             ke(i, j));
  }
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(entries.begin(), entries.end());

  std::vector<char> boundary(mesh.num_nodes(), 0);
  for (const Facet& f : mesh.facets)
    for (int v : f.node)
      boundary[v] = 1;
  Eigen::VectorXd exact(n);
  for (int i = 0; i < mesh.num_nodes(); ++i)
    exact.segment<d>(d * i) = A * Eigen::Matrix<double, d, 1>(mesh.nodes[i]) + c;
  std::vector<int> free, held;
  for (int i = 0; i < mesh.num_nodes(); ++i)
    for (int k = 0; k < d; ++k)
      (boundary[i] ? held : free).push_back(d * i + k);
  ASSERT_FALSE(free.empty()) << "the patch has no interior node";
  // K_ff u_f = -K_fh u_h, by selection matrices.
  auto selection = [n](const std::vector<int>& dofs) {
    Eigen::SparseMatrix<double> S(static_cast<int>(dofs.size()), n);
    for (std::size_t r = 0; r < dofs.size(); ++r)
      S.insert(static_cast<int>(r), dofs[r]) = 1;
    return S;
  };
  const Eigen::SparseMatrix<double> Sf = selection(free), Sh = selection(held);
  const Eigen::SparseMatrix<double> Kff = Sf * K * Sf.transpose();
  const Eigen::VectorXd rhs = -(Sf * K * Sh.transpose()) * (Sh * exact);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(Kff);
  ASSERT_EQ(solver.info(), Eigen::Success);
  const Eigen::VectorXd uf = solver.solve(rhs);
  EXPECT_LT((uf - Sf * exact).cwiseAbs().maxCoeff(), 1e-12);

  Eigen::VectorXd u = exact;
  for (std::size_t r = 0; r < free.size(); ++r)
    u[free[r]] = uf[static_cast<int>(r)];
  const auto strain = voigt_strain<d>(A);
  for (int t = 0; t < mesh.num_cells(); ++t) {
    Eigen::Matrix<double, d*(d + 1), 1> ue;
    for (int i = 0; i <= d; ++i)
      ue.template segment<d>(d * i) = u.segment<d>(d * mesh.cells[t][i]);
    const auto b =
        p1_simplex_strain_matrix<d>(p1_simplex_gradients<d>(simplex_vertices<d>(mesh, t)));
    EXPECT_LT((b * ue - strain).cwiseAbs().maxCoeff(), 1e-12) << "cell " << t;
    EXPECT_LT((D * (b * ue) - D * strain).cwiseAbs().maxCoeff(), 1e-10) << "cell " << t;
  }
}

Mesh cube() {
  // gmsh's unstructured cube of tetrahedra (tests/mesh/test_gmsh_3d.cpp).
  return read_gmsh(std::filesystem::path(SIG_SOURCE_DIR) / "tests" / "fuzz" / "corpus" / "gmsh" /
                   "box_v41_ascii.msh");
}

TEST(P1Simplex, PatchTestOnUnstructuredTetrahedra) {
  patch_test<3>(cube());
}

TEST(P1Simplex, PatchTestOnAPerturbedTriangleMesh) {
  patch_test<2>(test::perturbed_rectangle(2, 1, 6, 4));
}

TEST(P1Simplex, TetrahedronGradientsAndRigidMotions) {
  SimplexVertices<3> x;
  x << 0.1, 1.2, 0.2, 0.3, //
      0.0, 0.1, 0.9, 0.2,  //
      0.05, 0.0, 0.1, 1.1;
  EXPECT_GT(p1_measure<3>(x), 0);
  const SimplexVertices<3> g = p1_simplex_gradients<3>(x);
  // grad lambda_i . (x_j - x_0) = delta_ij - delta_0j... : the gradients reproduce x itself.
  EXPECT_LT((x * g.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-14);
  EXPECT_LT(g.rowwise().sum().norm(), 1e-14);
  Hooke law;
  law.E = 3;
  law.nu = 0.25;
  const SimplexMatrix<3> K = p1_simplex_stiffness<3>(x, law.D3(), 1.0);
  EXPECT_LT((K - K.transpose()).norm(), 1e-13 * K.norm());
  // The six rigid motions: three translations, three infinitesimal rotations.
  for (int m = 0; m < 6; ++m) {
    Eigen::Matrix<double, 12, 1> u;
    for (int i = 0; i < 4; ++i) {
      const Eigen::Vector3d p = x.col(i);
      u.segment<3>(3 * i) =
          m < 3 ? Eigen::Vector3d(Eigen::Vector3d::Unit(m)) : Eigen::Vector3d::Unit(m - 3).cross(p);
    }
    EXPECT_LT((K * u).norm(), 1e-13 * K.norm()) << "motion " << m;
  }
  Eigen::SelfAdjointEigenSolver<SimplexMatrix<3>> spectrum(K);
  EXPECT_GT(spectrum.eigenvalues()(6), 1e-8 * K.norm()); // rank 6 exactly
}

TEST(P1Simplex, TheTriangleKernelsAreItsTwoDimensionalCase) {
  Matrix23 x;
  x << 0.0, 1.2, 0.3, //
      0.0, 0.3, 0.7;
  Hooke law;
  law.E = 5;
  law.nu = 0.2;
  EXPECT_EQ(p1_stiffness(x, law.D(), 0.5), p1_simplex_stiffness<2>(x, law.D(), 0.5));
  EXPECT_EQ(p1_area(x), p1_measure<2>(x));
}

} // namespace
} // namespace sig
