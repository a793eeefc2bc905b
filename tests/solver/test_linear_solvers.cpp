// Every linear backend on the same manufactured problems (MFEM's test_direct_solvers habit):
// residual and error of a known solution, several right sides, a refactorization with new values
// on the analyzed pattern, and failures that must be errors rather than wrong numbers.
#include "solver/cholmod_solver.hpp"
#include "solver/linear_solver.hpp"
#include "solver/mumps_solver.hpp"
#include "solver/umfpack_solver.hpp"
#include "test_linear_problems.hpp"

#include "core/error.hpp"

#include <gtest/gtest.h>

#include <string>

namespace sig {
namespace {

struct Backend {
  std::string name;
  MatrixKind kind;
};

std::string backend_label(const testing::TestParamInfo<Backend>& info) {
  return info.param.name + "_" + to_string(info.param.kind);
}

class LinearSolverTest : public testing::TestWithParam<Backend> {
protected:
  std::unique_ptr<LinearSolver> make() const {
    return make_linear_solver(GetParam().name, GetParam().kind);
  }
};

double relative_residual(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& X,
                         const Eigen::MatrixXd& B) {
  return (A * X - B).norm() / B.norm();
}

// A 2D elasticity stiffness (3362 dofs before clamping) with a known solution.
TEST_P(LinearSolverTest, SolvesManufacturedElasticity) {
  const Eigen::SparseMatrix<double> A = test::clamped_stiffness({40, 40});
  const Eigen::VectorXd x = test::manufactured(static_cast<int>(A.rows()));
  const Eigen::VectorXd b = A * x;
  auto solver = make();
  solver->analyze(A);
  solver->factorize(A);
  const Eigen::VectorXd u = solver->solve(b);
  EXPECT_LT(relative_residual(A, u, b), 1e-12);
  EXPECT_LT((u - x).norm() / x.norm(), 1e-10);
  EXPECT_EQ(solver->name(), GetParam().name);
}

TEST_P(LinearSolverTest, SolvesSeveralRightSides) {
  const Eigen::SparseMatrix<double> A = test::clamped_stiffness({30, 20});
  const int n = static_cast<int>(A.rows());
  Eigen::MatrixXd X(n, 3);
  for (int j = 0; j < 3; ++j)
    X.col(j) = test::manufactured(n, 0.7 * j);
  const Eigen::MatrixXd B = A * X;
  auto solver = make();
  solver->factorize(A); // analyzes by itself
  const Eigen::MatrixXd U = solver->solve(B);
  ASSERT_EQ(U.cols(), 3);
  EXPECT_LT(relative_residual(A, U, B), 1e-12);
  EXPECT_LT((U - X).norm() / X.norm(), 1e-10);
  for (int j = 0; j < 3; ++j) // each column agrees with a single solve
    EXPECT_LT((U.col(j) - solver->solve(Eigen::VectorXd(B.col(j)))).norm(), 1e-12 * X.norm());
}

// A Newton loop: one analysis, then new values on the same pattern at every iteration.
TEST_P(LinearSolverTest, RefactorizesNewValuesOnAnalyzedPattern) {
  const Eigen::SparseMatrix<double> A = test::clamped_stiffness({30, 30});
  const int n = static_cast<int>(A.rows());
  auto solver = make();
  solver->analyze(A);
  solver->factorize(A);
  Eigen::SparseMatrix<double> A2 = 2.5 * A;
  for (int k = 0; k < n; ++k)
    A2.coeffRef(k, k) += 0.1 * (1 + k % 7); // diagonal is in pattern
  ASSERT_EQ(A2.nonZeros(), A.nonZeros());
  const Eigen::VectorXd x = test::manufactured(n, 1.3);
  const Eigen::VectorXd b = A2 * x;
  solver->factorize(A2);
  const Eigen::VectorXd u = solver->solve(b);
  EXPECT_LT(relative_residual(A2, u, b), 1e-12);
  EXPECT_LT((u - x).norm() / x.norm(), 1e-10);
  // and back to the first matrix
  solver->factorize(A);
  EXPECT_LT(relative_residual(A, solver->solve(Eigen::VectorXd(A * x)), A * x), 1e-12);
}

// Same size and entry count, different pattern: the analysis must be redone, not reused.
TEST_P(LinearSolverTest, NewPatternIsAnalyzedAgain) {
  constexpr int n = 60;
  auto coupled = [](int far) {
    std::vector<Eigen::Triplet<double>> t;
    for (int k = 0; k < n; ++k) {
      t.emplace_back(k, k, 4.0);
      if (k > 0) t.emplace_back(k, k - 1, -1.0);
      if (k + 1 < n) t.emplace_back(k, k + 1, -1.0);
    }
    t.emplace_back(0, far, -0.5);
    t.emplace_back(far, 0, -0.5);
    Eigen::SparseMatrix<double> A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    return A;
  };
  const Eigen::SparseMatrix<double> A1 = coupled(5), A2 = coupled(9);
  ASSERT_EQ(A1.nonZeros(), A2.nonZeros());
  EXPECT_NE(pattern_fingerprint(A1), pattern_fingerprint(A2));
  auto solver = make();
  solver->factorize(A1);
  solver->factorize(A2);
  const Eigen::VectorXd x = test::manufactured(n);
  EXPECT_LT((solver->solve(A2 * x) - x).norm() / x.norm(), 1e-12);
}

TEST_P(LinearSolverTest, SolveBeforeFactorizeIsAnError) {
  auto solver = make();
  EXPECT_THROW(solver->solve(Eigen::VectorXd::Ones(4)), Error);
}

TEST_P(LinearSolverTest, WrongRightSideSizeIsAnError) {
  const Eigen::SparseMatrix<double> A = test::clamped_stiffness({4, 4});
  auto solver = make();
  solver->factorize(A);
  EXPECT_THROW(solver->solve(Eigen::VectorXd::Ones(A.rows() + 1)), Error);
}

INSTANTIATE_TEST_SUITE_P(
    AllBackends, LinearSolverTest,
    testing::Values(Backend{"cholmod", MatrixKind::spd}, Backend{"umfpack", MatrixKind::spd},
                    Backend{"umfpack", MatrixKind::general}, Backend{"mumps", MatrixKind::spd},
                    Backend{"mumps", MatrixKind::symmetric}, Backend{"mumps", MatrixKind::general}),
    backend_label);

/// tridiag(-1, d, -1) of size n: positive definite for d >= 2, indefinite for d < 2 cos(pi/(n+1)).
Eigen::SparseMatrix<double> laplacian_1d(int n, double d) {
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < n; ++k) {
    t.emplace_back(k, k, d);
    if (k > 0) t.emplace_back(k, k - 1, -1.0);
    if (k + 1 < n) t.emplace_back(k, k + 1, -1.0);
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

/// diag(1, 2, 0, 4, ...) with the zero stored: exactly singular whatever the pivoting.
Eigen::SparseMatrix<double> singular_diagonal(int n) {
  Eigen::SparseMatrix<double> A(n, n);
  for (int k = 0; k < n; ++k)
    A.insert(k, k) = (k == 2) ? 0.0 : 1.0 + k;
  A.makeCompressed();
  return A;
}

TEST(LinearSolverFactory, UnknownNameListsTheChoices) {
  try {
    make_linear_solver("pardiso", MatrixKind::spd);
    FAIL() << "no error for an unknown backend";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("pardiso"), std::string::npos) << what;
    for (const char* choice : {"cholmod", "umfpack", "mumps"})
      EXPECT_NE(what.find(choice), std::string::npos) << what;
  }
}

TEST(LinearSolverFactory, NamesAreCaseInsensitive) {
  EXPECT_EQ(make_linear_solver("MUMPS", MatrixKind::general)->name(), "mumps");
}

TEST(LinearSolverFactory, CholmodRefusesMatricesThatAreNotSpd) {
  EXPECT_THROW(make_linear_solver("cholmod", MatrixKind::general), Error);
  EXPECT_THROW(make_linear_solver("cholmod", MatrixKind::symmetric), Error);
}

// The kind a backend's traits give a symmetric matrix is one its factory takes, and it solves a
// positive definite one; an unknown name is refused as by the factory.
TEST(BackendTraits, SymmetricKindIsOneTheBackendFactorizes) {
  const Eigen::SparseMatrix<double> A = laplacian_1d(100, 2.5);
  const Eigen::VectorXd x = test::manufactured(100);
  for (const char* backend : {"cholmod", "umfpack", "MUMPS"}) {
    const auto solver = make_linear_solver(backend, backend_traits(backend).symmetric_kind());
    solver->factorize(A);
    EXPECT_LT((solver->solve(Eigen::VectorXd(A * x)) - x).norm() / x.norm(), 1e-12) << backend;
  }
  EXPECT_THROW(backend_traits("pardiso"), Error);
}

TEST(Cholmod, IndefiniteMatrixIsAnErrorNamingTheMinor) {
  const Eigen::SparseMatrix<double> A = laplacian_1d(50, 0.9); // eigenvalues in (-1.1, 2.9), none 0
  CholmodSolver solver;
  try {
    solver.factorize(A);
    FAIL() << "CHOLMOD factorized an indefinite matrix";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not positive definite"), std::string::npos) << e.what();
  }
  EXPECT_THROW(solver.solve(Eigen::VectorXd::Ones(50)), Error); // no factor left to use
}

TEST(Cholmod, SingularMatrixIsAnError) {
  EXPECT_THROW(CholmodSolver().factorize(singular_diagonal(10)), Error);
}

TEST(Cholmod, OrdersWithMetis) {
  CholmodSolver solver;
  solver.analyze(test::clamped_stiffness({10, 10}));
  EXPECT_EQ(solver.ordering(), "metis");
}

TEST(Umfpack, SingularMatrixIsAnError) {
  UmfpackSolver solver;
  try {
    solver.factorize(singular_diagonal(10));
    FAIL() << "UMFPACK factorized a singular matrix";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos) << e.what();
  }
  EXPECT_THROW(solver.solve(Eigen::VectorXd::Ones(10)), Error);
}

TEST(Umfpack, OrdersWithMetis) {
  UmfpackSolver solver(MatrixKind::general);
  solver.analyze(test::clamped_stiffness({10, 10}));
  EXPECT_EQ(solver.ordering(), "metis");
}

TEST(Mumps, OrdersWithAmdBelowTwoHundredThousandUnknowns) {
  MumpsSolver solver(MatrixKind::symmetric);
  solver.analyze(test::clamped_stiffness({10, 10}));
  EXPECT_EQ(solver.ordering(), "amd");
  // Above it, MUMPS's automatic choice: nested dissection (Scotch or PORD) on this 2D grid.
  const Eigen::SparseMatrix<double> large = test::clamped_stiffness({320, 320});
  ASSERT_GT(large.rows(), 200000);
  solver.analyze(large);
  EXPECT_NE(solver.ordering(), "amd");
  EXPECT_NE(solver.ordering(), "");
}

// Rows denser than a 2D P1 mesh's (a 3D P1 row has about 45 entries) take MUMPS's automatic
// choice at any size: AMD's fill on a 3D mesh made the factorization of the 158k-unknown half ball
// 5x slower (mumps_solver.cpp). Here a 3D-like matrix of 1536 unknowns: the 27-point stencil of an
// 8 x 8 x 8 grid (diagonally dominant) times a 3 x 3 SPD block, 81 entries per inner row.
TEST(Mumps, OrdersDenseRowsWithNestedDissectionAtAnySize) {
  constexpr int m = 8, n = m * m * m;
  const Eigen::Matrix3d B = (Eigen::Matrix3d() << 2, 1, 0, 1, 2, 1, 0, 1, 2).finished();
  std::vector<Eigen::Triplet<double>> t;
  const auto at = [](int i, int j, int k) { return (i * m + j) * m + k; };
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < m; ++j)
      for (int k = 0; k < m; ++k)
        for (int di = -1; di <= 1; ++di)
          for (int dj = -1; dj <= 1; ++dj)
            for (int dk = -1; dk <= 1; ++dk) {
              const int I = i + di, J = j + dj, K = k + dk;
              if (I < 0 || J < 0 || K < 0 || I >= m || J >= m || K >= m) continue;
              const double v = (di == 0 && dj == 0 && dk == 0) ? 27.0 : -1.0;
              for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b)
                  if (B(a, b) != 0)
                    t.emplace_back(3 * at(i, j, k) + a, 3 * at(I, J, K) + b, v * B(a, b));
            }
  Eigen::SparseMatrix<double> A(3 * n, 3 * n);
  A.setFromTriplets(t.begin(), t.end());
  ASSERT_GT(double(A.nonZeros()) / double(A.rows()), 30.0);
  MumpsSolver solver(MatrixKind::spd);
  solver.analyze(A);
  EXPECT_NE(solver.ordering(), "amd");
  EXPECT_NE(solver.ordering(), "");
  const Eigen::VectorXd x = test::manufactured(3 * n);
  solver.factorize(A);
  EXPECT_LE((solver.solve(Eigen::VectorXd(A * x)) - x).norm(), 1e-10 * x.norm());
}

// An uncompressed matrix (room left in its columns) refills MUMPS's values from its compressed
// copy: the same solution as the compressed matrix, before and after a change of values.
TEST(Mumps, UncompressedMatrixSolvesAsItsCompressedCopy) {
  const int n = 30;
  Eigen::SparseMatrix<double> loose(n, n);
  loose.reserve(Eigen::VectorXi::Constant(n, 5));
  for (int k = 0; k < n; ++k) {
    loose.insert(k, k) = 3.0;
    if (k > 0) loose.insert(k, k - 1) = -1.0;
    if (k + 1 < n) loose.insert(k, k + 1) = -1.0;
  }
  ASSERT_FALSE(loose.isCompressed());
  const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, 1.0, 2.0);
  MumpsSolver solver(MatrixKind::symmetric); // the second factorization reuses the analysis
  for (double diagonal : {3.0, 5.0}) {
    for (int k = 0; k < n; ++k)
      loose.coeffRef(k, k) = diagonal;
    Eigen::SparseMatrix<double> tight = loose;
    tight.makeCompressed();
    solver.factorize(loose);
    const Eigen::VectorXd x = solver.solve(b);
    EXPECT_LT((tight * x - b).norm(), 1e-12 * b.norm()) << "diagonal " << diagonal;
  }
}

TEST(Mumps, SingularMatrixIsAnError) {
  for (MatrixKind kind : {MatrixKind::general, MatrixKind::symmetric}) {
    MumpsSolver solver(kind);
    try {
      solver.factorize(singular_diagonal(10));
      FAIL() << "MUMPS factorized a singular matrix, kind " << to_string(kind);
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("INFOG(1) = -10"), std::string::npos) << e.what();
    }
  }
}

TEST(Mumps, IndefiniteMatrixDeclaredSpdIsAnError) {
  MumpsSolver solver(MatrixKind::spd);
  EXPECT_THROW(solver.factorize(laplacian_1d(50, 0.9)), Error);
}

TEST(Mumps, SymmetricIndefiniteMatrixIsSolved) {
  const Eigen::SparseMatrix<double> A = laplacian_1d(200, 0.9);
  const Eigen::VectorXd x = test::manufactured(200);
  MumpsSolver solver(MatrixKind::symmetric);
  solver.factorize(A);
  EXPECT_LT((solver.solve(Eigen::VectorXd(A * x)) - x).norm() / x.norm(), 1e-10);
}

// The general backends must read both triangles: a convection term makes A unsymmetric.
TEST(LinearSolverGeneral, UnsymmetricMatrixIsSolved) {
  const int n = 400;
  Eigen::SparseMatrix<double> A = laplacian_1d(n, 2.5);
  for (int k = 0; k + 1 < n; ++k) {
    A.coeffRef(k, k + 1) += 0.8;
    A.coeffRef(k + 1, k) -= 0.8;
  }
  const Eigen::VectorXd x = test::manufactured(n);
  const Eigen::VectorXd b = A * x;
  for (const char* name : {"umfpack", "mumps"}) {
    auto solver = make_linear_solver(name, MatrixKind::general);
    solver->factorize(A);
    const Eigen::VectorXd u = solver->solve(b);
    EXPECT_LT(relative_residual(A, u, b), 1e-12) << name;
    EXPECT_LT((u - x).norm() / x.norm(), 1e-10) << name;
  }
}

} // namespace
} // namespace sig
