#include "solver/linear_solver.hpp"

#include "core/error.hpp"
#include "solver/cholmod_solver.hpp"
#include "solver/mumps_solver.hpp"
#include "solver/umfpack_solver.hpp"

#include <algorithm>
#include <cctype>

namespace sig {

LinearSolver::~LinearSolver() = default;

Eigen::MatrixXd LinearSolver::solve(const Eigen::MatrixXd& B) const {
  Eigen::MatrixXd X(B.rows(), B.cols());
  for (Eigen::Index j = 0; j < B.cols(); ++j)
    X.col(j) = solve(Eigen::VectorXd(B.col(j)));
  return X;
}

std::uint64_t pattern_fingerprint(const Eigen::SparseMatrix<double>& A) {
  // FNV-1a over the pattern: a few milliseconds for a million entries, nothing next to a
  // factorization, and it catches a caller who changed the pattern between two factorize().
  std::uint64_t h = 14695981039346656037ull;
  auto mix = [&h](std::uint64_t v) {
    h ^= v;
    h *= 1099511628211ull;
  };
  mix(static_cast<std::uint64_t>(A.rows()));
  mix(static_cast<std::uint64_t>(A.cols()));
  for (int j = 0; j < A.outerSize(); ++j) {
    mix(0xffffffffull); // column separator
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it)
      mix(static_cast<std::uint64_t>(it.row()));
  }
  return h;
}

std::string to_string(MatrixKind kind) {
  switch (kind) {
  case MatrixKind::spd:
    return "spd";
  case MatrixKind::symmetric:
    return "symmetric";
  case MatrixKind::general:
    return "general";
  }
  return "?";
}

std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name, MatrixKind kind) {
  std::string key = name;
  std::transform(key.begin(), key.end(), key.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  if (key == "cholmod") {
    SIG_VERIFY(kind == MatrixKind::spd, "linear solver 'cholmod' factorizes spd matrices only, not "
                                            << to_string(kind) << " ones: use umfpack or mumps");
    return std::make_unique<CholmodSolver>();
  }
  if (key == "umfpack") return std::make_unique<UmfpackSolver>(kind);
  if (key == "mumps") return std::make_unique<MumpsSolver>(kind);
  SIG_VERIFY(false,
             "unknown linear solver '" << name << "' (choices: " << linear_solver_names << ")");
  return nullptr;
}

} // namespace sig
