// Static condensation onto interface dofs: S against the dense formula, the semi-coercive case
// (singular K, positive definite K_ii), and MUMPS's partial factorization against the generic
// block solves.
#include "solver/cholmod_simplicial.hpp"
#include "solver/cholmod_split.hpp"
#include "solver/schur.hpp"
#include "test_linear_problems.hpp"

#include "core/error.hpp"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

namespace sig {
namespace {

class SchurTest : public testing::TestWithParam<std::string> {};

// K clamped on its left edge, interface = the top edge: compare with dense linear algebra.
TEST_P(SchurTest, MatchesDenseFormulaOnSpdMatrix) {
  const test::Grid g{7, 5};
  const Eigen::SparseMatrix<double> K = test::clamped_stiffness(g);
  const int n = static_cast<int>(K.rows());
  // free dofs are numbered after removing the left edge: node (i, j) with i > 0 has free index
  // 2 (j nx + i - 1) + a; the top edge is j = ny.
  std::vector<int> c;
  for (int i = 1; i <= g.nx; ++i)
    for (int a = 0; a < 2; ++a)
      c.push_back(2 * (g.ny * g.nx + i - 1) + a);
  const std::vector<int> i_dofs = test::complement(c, n);

  SchurComplement schur(K, c, GetParam());
  const Eigen::MatrixXd Kd(K);
  auto block = [&](const std::vector<int>& r, const std::vector<int>& s) {
    return test::dense_block(Kd, r, s);
  };
  const Eigen::MatrixXd K_ii = block(i_dofs, i_dofs), K_ic = block(i_dofs, c);
  const Eigen::LLT<Eigen::MatrixXd> llt(K_ii);
  const Eigen::MatrixXd S = block(c, c) - K_ic.transpose() * llt.solve(K_ic);
  EXPECT_LT((schur.matrix() - S).norm(), 1e-12 * S.norm());
  EXPECT_EQ(schur.interface_dofs(), c);
  EXPECT_EQ(schur.interior_dofs(), i_dofs);

  // condense, solve the small system, expand: the solution of the full system
  const Eigen::VectorXd x = test::manufactured(n);
  const Eigen::VectorXd f = K * x;
  const Eigen::VectorXd u_c = schur.matrix().llt().solve(schur.condense(f));
  const Eigen::VectorXd u = schur.expand(f, u_c);
  EXPECT_LT((u - x).norm() / x.norm(), 1e-10);
}

// Semi-coercive: the free-floating rectangle (K has the 3 rigid motions as kernel) with the
// whole boundary as interface, so that K_ii is positive definite and K is never factorized.
TEST_P(SchurTest, SingularStiffnessWithClampedInteriorIsCondensed) {
  const test::Grid g{12, 9};
  const Eigen::SparseMatrix<double> K = test::elasticity_stiffness(g);
  const std::vector<int> c = test::dofs_where(g, [&](int i, int j) { return g.on_boundary(i, j); });
  SchurComplement schur(K, c, GetParam());
  const Eigen::MatrixXd& S = schur.matrix();
  const int m = static_cast<int>(c.size());
  ASSERT_EQ(S.rows(), m);
  EXPECT_EQ((S - S.transpose()).norm(), 0.0);

  // Kernel: the rigid motions restricted to the interface, and nothing else.
  const Eigen::MatrixXd R = test::rigid_modes(g);
  Eigen::MatrixXd R_c(m, 3);
  for (int k = 0; k < m; ++k)
    R_c.row(k) = R.row(c[k]);
  EXPECT_LT((S * R_c).norm(), 1e-12 * S.norm() * R_c.norm());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(S);
  const Eigen::VectorXd lambda = eig.eigenvalues(); // ascending
  const double scale = lambda[m - 1];
  for (int k = 0; k < 3; ++k)
    EXPECT_LT(std::abs(lambda[k]), 1e-12 * scale) << k;
  EXPECT_GT(lambda[3], 1e-6 * scale); // positive semi-definite with a 3-dimensional kernel

  // A consistent load (f = K x is orthogonal to the kernel): the exact interface values give
  // back x, and any solution of the singular S u_c = g gives x up to a rigid motion.
  const Eigen::VectorXd x = test::manufactured(g.dofs());
  const Eigen::VectorXd f = K * x;
  Eigen::VectorXd x_c(m);
  for (int k = 0; k < m; ++k)
    x_c[k] = x[c[k]];
  EXPECT_LT((schur.expand(f, x_c) - x).norm() / x.norm(), 1e-10);
  const Eigen::VectorXd gc = schur.condense(f);
  EXPECT_LT((S * x_c - gc).norm(), 1e-10 * gc.norm());
  EXPECT_LT((R_c.transpose() * gc).norm(), 1e-10 * gc.norm()); // compatible right side

  // minimum-norm solution of the singular interface problem through the eigenbasis
  Eigen::VectorXd u_c = Eigen::VectorXd::Zero(m);
  for (int k = 3; k < m; ++k)
    u_c += eig.eigenvectors().col(k) * (eig.eigenvectors().col(k).dot(gc) / lambda[k]);
  const Eigen::VectorXd u = schur.expand(f, u_c);
  EXPECT_LT((K * u - f).norm() / f.norm(), 1e-10);
  const Eigen::VectorXd d = u - x; // must be rigid: its projection on the rigid modes is itself
  const Eigen::VectorXd rigid = R * R.colPivHouseholderQr().solve(d);
  EXPECT_LT((d - rigid).norm(), 1e-9 * x.norm());
}

TEST_P(SchurTest, InvalidInterfaceIsAnError) {
  const Eigen::SparseMatrix<double> K = test::clamped_stiffness({4, 4});
  const int n = static_cast<int>(K.rows());
  EXPECT_THROW(SchurComplement(K, {}, GetParam()), Error);
  EXPECT_THROW(SchurComplement(K, {3, 1}, GetParam()), Error);
  EXPECT_THROW(SchurComplement(K, {1, 1}, GetParam()), Error);
  EXPECT_THROW(SchurComplement(K, {0, n}, GetParam()), Error);
  SchurComplement schur(K, {0, 1}, GetParam());
  EXPECT_THROW(schur.condense(Eigen::VectorXd::Zero(n - 1)), Error);
  EXPECT_THROW(schur.expand(Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(3)), Error);
}

INSTANTIATE_TEST_SUITE_P(AllBackends, SchurTest, testing::Values("cholmod", "umfpack", "mumps"));

// MUMPS's partial factorization (ICNTL(19)) and the block solves of CHOLMOD agree on a 2D
// elasticity problem of a few thousand dofs, the interface being the bottom edge and the lower
// sides (a contact zone), K free-floating.
TEST(Schur, MumpsPartialFactorizationMatchesBlockSolves) {
  const test::Grid g{40, 30};
  const Eigen::SparseMatrix<double> K = test::elasticity_stiffness(g);
  const std::vector<int> c = test::dofs_where(
      g, [&](int i, int j) { return j == 0 || ((i == 0 || i == g.nx) && j <= 10); });
  SchurComplement mumps(K, c, "mumps");
  SchurComplement cholmod(K, c, "cholmod");
  const Eigen::MatrixXd& S = cholmod.matrix();
  EXPECT_LT((mumps.matrix() - S).norm(), 1e-10 * S.norm());
  EXPECT_EQ((mumps.matrix() - mumps.matrix().transpose()).norm(), 0.0);

  const Eigen::VectorXd x = test::manufactured(g.dofs(), 0.4);
  const Eigen::VectorXd f = K * x;
  EXPECT_LT((mumps.condense(f) - cholmod.condense(f)).norm(), 1e-10 * f.norm());
  Eigen::VectorXd x_c(c.size());
  for (size_t k = 0; k < c.size(); ++k)
    x_c[Eigen::Index(k)] = x[c[k]];
  // The expansion continues the condensation's solve (ICNTL(26)); another load, or a second
  // expansion of the same, takes the interior solve.
  EXPECT_LT((mumps.expand(f, x_c) - x).norm() / x.norm(), 1e-10);
  EXPECT_LT((mumps.expand(f, x_c) - x).norm() / x.norm(), 1e-10);
  EXPECT_LT((mumps.expand(2.0 * f, 2.0 * x_c) - 2.0 * x).norm() / x.norm(), 1e-10);
  EXPECT_LT((mumps.condense(2.0 * f) - 2.0 * cholmod.condense(f)).norm(), 1e-10 * f.norm());
  EXPECT_LT((mumps.expand(2.0 * f, 2.0 * x_c) - 2.0 * x).norm() / x.norm(), 1e-10);
  EXPECT_GT(mumps.seconds_factorize(), 0.0);
}

// Also for a symmetric K_ii factorized as indefinite (MUMPS SYM = 2): same S.
TEST(Schur, MumpsSymmetricKindMatchesSpdKind) {
  const test::Grid g{10, 8};
  const Eigen::SparseMatrix<double> K = test::elasticity_stiffness(g);
  const std::vector<int> c = test::dofs_where(g, [](int, int j) { return j == 0; });
  SchurComplement spd(K, c, "mumps", MatrixKind::spd);
  SchurComplement sym(K, c, "mumps", MatrixKind::symmetric);
  SchurComplement lu(K, c, "umfpack", MatrixKind::general);
  EXPECT_LT((spd.matrix() - sym.matrix()).norm(), 1e-10 * spd.matrix().norm());
  EXPECT_LT((spd.matrix() - lu.matrix()).norm(), 1e-10 * spd.matrix().norm());
}

} // namespace
} // namespace sig

namespace sig {
namespace {

/// S = K_cc - K_ci K_ii^-1 K_ic, dense.
Eigen::MatrixXd dense_schur(const Eigen::SparseMatrix<double>& K, const std::vector<int>& c) {
  const Eigen::MatrixXd Kd(K);
  const std::vector<int> i_dofs = test::complement(c, static_cast<int>(K.rows()));
  const Eigen::MatrixXd K_ic = test::dense_block(Kd, i_dofs, c);
  const Eigen::LLT<Eigen::MatrixXd> llt(test::dense_block(Kd, i_dofs, i_dofs));
  return test::dense_block(Kd, c, c) - K_ic.transpose() * llt.solve(K_ic);
}

/// What expect_dense_formulas used: the load f = K x, the interface values u_c expanded into u.
struct SplitCheck {
  Eigen::MatrixXd S;
  Eigen::VectorXd x, f, u_c, u;
};

/// The split's S, condensed load and expansion (of any interface values) against the dense
/// formulas S = K_cc - K_ci K_ii^-1 K_ic, f_c - K_ci K_ii^-1 f_i, K_ii^-1 (f_i - K_ic u_c).
SplitCheck expect_dense_formulas(CholmodSplitSolver& split, const Eigen::SparseMatrix<double>& K,
                                 const std::vector<int>& c) {
  const int n = static_cast<int>(K.rows());
  const std::vector<int> i_dofs = test::complement(c, n);
  const Eigen::MatrixXd Kd(K);
  const Eigen::MatrixXd K_ic = test::dense_block(Kd, i_dofs, c);
  const Eigen::LLT<Eigen::MatrixXd> llt(test::dense_block(Kd, i_dofs, i_dofs));
  SplitCheck check;
  check.S = dense_schur(K, c);
  EXPECT_LT((split.schur_complement() - check.S).norm(), 1e-12 * check.S.norm()) << n;
  check.x = test::manufactured(n);
  check.f = K * check.x;
  Eigen::VectorXd f_i(i_dofs.size()), f_c(c.size());
  for (size_t k = 0; k < i_dofs.size(); ++k)
    f_i[k] = check.f[i_dofs[k]];
  for (size_t k = 0; k < c.size(); ++k)
    f_c[k] = check.f[c[k]];
  const Eigen::VectorXd condensed = f_c - K_ic.transpose() * llt.solve(f_i);
  EXPECT_LT((split.reduce(check.f) - condensed).norm(), 1e-12 * condensed.norm()) << n;
  check.u_c = test::manufactured(static_cast<int>(c.size()), 0.7);
  check.u = split.expand(check.u_c);
  const Eigen::VectorXd u_i = llt.solve(f_i - K_ic * check.u_c);
  for (size_t k = 0; k < c.size(); ++k)
    EXPECT_EQ(check.u[c[k]], check.u_c[k]);
  for (size_t k = 0; k < i_dofs.size(); ++k)
    EXPECT_NEAR(check.u[i_dofs[k]], u_i[k], 1e-11 * u_i.norm()) << n;
  return check;
}

// The CHOLMOD split (solver/cholmod_split.hpp): K factorized whole with the interface last. S is
// the factor's trailing block squared, the condensed load and the expansion of ANY interface
// values are the dense formulas', and the pair solves K x = f when the interface values are
// S^-1 of the condensed load; SchurComplement takes that path on request and agrees with the
// interior one, and falls back to it for a K that is not positive definite.
TEST(Schur, CholmodSplitMatchesTheDenseFormulas) {
  const test::Grid g{9, 6};
  const Eigen::SparseMatrix<double> K = test::clamped_stiffness(g);
  const int n = static_cast<int>(K.rows());
  std::vector<int> c;
  for (int i = 1; i <= g.nx; ++i)
    for (int a = 0; a < 2; ++a)
      c.push_back(2 * (i - 1) + a); // the bottom edge, low numbers: the split must move them last
  CholmodSplitSolver split(K, c);
  const SplitCheck check = expect_dense_formulas(split, K, c);
  const Eigen::VectorXd &f = check.f, &u_c = check.u_c, &u = check.u;
  const Eigen::MatrixXd& S = check.S;
  EXPECT_THROW(split.expand(u_c), Error); // one expand per reduce

  SchurComplement whole(K, c, "cholmod", MatrixKind::spd, true), apart(K, c, "cholmod");
  EXPECT_LT((whole.matrix() - apart.matrix()).norm(), 1e-12 * S.norm());
  const Eigen::VectorXd x = whole.expand(f, whole.matrix().llt().solve(whole.condense(f)));
  EXPECT_LT((x - test::manufactured(n)).norm(), 1e-10 * x.norm());
  // A second expansion of the same load (no condense between) redoes the forward substitution.
  EXPECT_LT((whole.expand(f, u_c) - u).norm(), 1e-11 * u.norm());

  // The free-floating body: K singular, K_ii (boundary held) positive definite.
  const test::Grid h{6, 5};
  const Eigen::SparseMatrix<double> floating = test::elasticity_stiffness(h);
  const std::vector<int> boundary =
      test::dofs_where(h, [&](int i, int j) { return h.on_boundary(i, j); });
  EXPECT_THROW(CholmodSplitSolver(floating, boundary), Error);
  SchurComplement fallback(floating, boundary, "cholmod", MatrixKind::spd, true);
  SchurComplement interior(floating, boundary, "cholmod");
  EXPECT_LT((fallback.matrix() - interior.matrix()).norm(), 1e-12 * interior.matrix().norm());
}

// The benchmark's floor (sig-bench-quasistatic): a plain solve with the simplicial factor.
TEST(Schur, CholmodSimplicialSolvesTheClampedBody) {
  const test::Grid g{9, 6};
  const Eigen::SparseMatrix<double> K = test::clamped_stiffness(g);
  const Eigen::VectorXd u = test::manufactured(static_cast<int>(K.rows()));
  CholmodSimplicialSolver simplicial(K);
  EXPECT_LT((simplicial.solve(K * u) - u).norm(), 1e-10 * u.norm());
  EXPECT_LT((simplicial.solve(K * (2 * u)) - 2 * u).norm(), 2e-10 * u.norm()); // reused workspace
  const test::Grid h{6, 5};
  EXPECT_THROW(CholmodSimplicialSolver(test::elasticity_stiffness(h)), Error); // singular
}

} // namespace
} // namespace sig

namespace sig {
namespace {

// A symmetric positive semi-definite matrix with the pattern of a 3D stiffness: the nodes of an
// n x n x n lattice, 3 unknowns each, every node coupled to its 26 neighbours by an spd 3 x 3
// block (81 entries a row inside: above nested_dissection_entries_per_row, as a 3D P1 row);
// kernel the 3 translations. Unknowns 3 node + a, node = (k n + j) n + i.
Eigen::SparseMatrix<double> lattice_stiffness_3d(int n) {
  std::vector<Eigen::Triplet<double>> t;
  const auto node = [n](int i, int j, int k) { return (k * n + j) * n + i; };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (int dk = 0; dk <= 1; ++dk)
          for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
              const int a = node(i, j, k);
              if (i + di < 0 || i + di >= n || j + dj < 0 || j + dj >= n || k + dk >= n) continue;
              const int b = node(i + di, j + dj, k + dk);
              if (b <= a) continue; // each pair once
              Eigen::Matrix3d B = 0.2 * Eigen::Matrix3d::Ones();
              B.diagonal() += Eigen::Vector3d(1.0 + 0.1 * (a % 3), 1.3, 0.8 + 0.05 * (b % 5));
              for (int p = 0; p < 3; ++p)
                for (int q = 0; q < 3; ++q) {
                  t.emplace_back(3 * a + p, 3 * a + q, B(p, q));
                  t.emplace_back(3 * b + p, 3 * b + q, B(p, q));
                  t.emplace_back(3 * a + p, 3 * b + q, -B(p, q));
                  t.emplace_back(3 * b + p, 3 * a + q, -B(p, q));
                }
            }
  Eigen::SparseMatrix<double> K(3 * n * n * n, 3 * n * n * n);
  K.setFromTriplets(t.begin(), t.end());
  return K;
}

/// Every unknown of the lattice's nodes on the face k = 0 (a contact face).
std::vector<int> lattice_bottom(int n) {
  std::vector<int> c;
  for (int d = 0; d < 3 * n * n; ++d)
    c.push_back(d);
  return c;
}

// The supernodal split on both dimensions' patterns: K positive definite (2D: the rectangle
// clamped on its left edge, interface its bottom edge; 3D: the lattice with springs on its face
// i = 0, interface its bottom face), S, the condensed load and the expansion against the dense
// formulas, and the pair solving K x = f.
TEST(Schur, CholmodSupernodalSplitMatchesTheDenseFormulas) {
  const test::Grid g{9, 6};
  std::vector<int> edge;
  for (int i = 1; i <= g.nx; ++i)
    for (int a = 0; a < 2; ++a)
      edge.push_back(2 * (i - 1) + a);
  Eigen::SparseMatrix<double> lattice = lattice_stiffness_3d(6);
  for (int node = 0; node < 6 * 6 * 6; node += 6) // the nodes i = 0
    for (int a = 0; a < 3; ++a)
      lattice.coeffRef(3 * node + a, 3 * node + a) += 0.5;
  const std::pair<Eigen::SparseMatrix<double>, std::vector<int>> cases[] = {
      {test::clamped_stiffness(g), edge}, {lattice, lattice_bottom(6)}};
  for (const auto& [K, c] : cases) {
    CholmodSplitSolver split(K, c, SplitLayout::supernodal);
    const SplitCheck check = expect_dense_formulas(split, K, c);
    EXPECT_EQ((split.schur_complement() - split.schur_complement().transpose()).norm(), 0.0);
    EXPECT_THROW(split.expand(check.u_c), Error); // one expand per reduce
    const Eigen::VectorXd w = check.S.llt().solve(split.reduce(check.f));
    EXPECT_LT((split.expand(w) - check.x).norm(), 1e-10 * check.x.norm());
  }
}

// The 3D pattern goes to the supernodal split by itself (its rows are dense), also for a
// semi-coercive K (the free lattice: K_cc's shift keeps the factorization positive definite):
// S is the dense formula's, positive semi-definite with the translations as its kernel, and it
// agrees with MUMPS's partial factorization; a singular K_ii is refused.
TEST(Schur, SemiCoerciveThreeDimensionalPatternTakesTheSupernodalSplit) {
  const int n = 5;
  const Eigen::SparseMatrix<double> K = lattice_stiffness_3d(n);
  ASSERT_TRUE(prefers_nested_dissection(K));
  ASSERT_FALSE(prefers_nested_dissection(test::elasticity_stiffness({9, 6})));
  const std::vector<int> c = lattice_bottom(n);
  const int m = static_cast<int>(c.size());
  const Eigen::MatrixXd S = dense_schur(K, c);
  SchurComplement cholmod(K, c, "cholmod"), mumps(K, c, "mumps");
  EXPECT_LT((cholmod.matrix() - S).norm(), 1e-12 * S.norm());
  EXPECT_LT((mumps.matrix() - S).norm(), 1e-10 * S.norm());
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(m, 3); // the translations on the interface
  for (int k = 0; k < m; ++k)
    T(k, k % 3) = 1;
  EXPECT_LT((cholmod.matrix() * T).norm(), 1e-12 * S.norm());

  // A consistent load: the exact interface values give back x.
  const Eigen::VectorXd x = test::manufactured(static_cast<int>(K.rows()));
  const Eigen::VectorXd f = K * x;
  Eigen::VectorXd x_c(m);
  for (int k = 0; k < m; ++k)
    x_c[k] = x[c[k]];
  const Eigen::VectorXd gc = cholmod.condense(f);
  EXPECT_LT((S * x_c - gc).norm(), 1e-10 * gc.norm());
  EXPECT_LT((cholmod.expand(f, x_c) - x).norm() / x.norm(), 1e-10);

  // An interior unknown coupled to nothing: K_ii singular, refused.
  Eigen::SparseMatrix<double> loose = K;
  loose.conservativeResize(K.rows() + 1, K.cols() + 1);
  loose.makeCompressed();
  EXPECT_THROW(CholmodSplitSolver(loose, c, SplitLayout::supernodal), FactorizationFailure);
}

} // namespace
} // namespace sig
