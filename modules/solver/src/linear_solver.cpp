#include "solver/linear_solver.hpp"

#include "core/error.hpp"
#include "solver/cholmod_solver.hpp"
#include "solver/mumps_solver.hpp"
#include "solver/umfpack_solver.hpp"

#include <algorithm>
#include <cctype>

namespace sig {

namespace {

enum class Backend { cholmod, umfpack, mumps };

/// The backend called `name`, in any case: the one place a backend's name is read.
Backend backend_named(const std::string& name) {
  std::string key = name;
  std::transform(key.begin(), key.end(), key.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  if (key == "cholmod") return Backend::cholmod;
  if (key == "umfpack") return Backend::umfpack;
  if (key == "mumps") return Backend::mumps;
  SIG_VERIFY(false,
             "unknown linear solver '" << name << "' (choices: " << linear_solver_names << ")");
  return Backend::cholmod;
}

} // namespace

LinearSolver::~LinearSolver() = default;

Eigen::MatrixXd LinearSolver::solve(const Eigen::MatrixXd& B) const {
  Eigen::MatrixXd X(B.rows(), B.cols());
  for (Eigen::Index j = 0; j < B.cols(); ++j)
    X.col(j) = solve(Eigen::VectorXd(B.col(j)));
  return X;
}

std::uint64_t pattern_fingerprint(const Eigen::SparseMatrix<double>& A) {
  // FNV-1a over the pattern, catching a caller who changed it between two factorize(). Four
  // lanes hash a column's rows in turn: one lane's chain of dependent multiplies held the hash
  // to a few cycles per entry, about 1 % of a Newton iteration of the ring (issue 15).
  constexpr std::uint64_t prime = 1099511628211ull;
  std::uint64_t h[4] = {14695981039346656037ull, 14695981039346656037ull ^ 1,
                        14695981039346656037ull ^ 2, 14695981039346656037ull ^ 3};
  const auto mix = [](std::uint64_t& lane, std::uint64_t v) { lane = (lane ^ v) * prime; };
  mix(h[0], static_cast<std::uint64_t>(A.rows()));
  mix(h[0], static_cast<std::uint64_t>(A.cols()));
  const int* outer = A.outerIndexPtr();
  const int* counts = A.innerNonZeroPtr(); // null when compressed
  const int* inner = A.innerIndexPtr();
  for (Eigen::Index j = 0; j < A.outerSize(); ++j) {
    const int begin = outer[j], end = counts ? begin + counts[j] : outer[j + 1];
    mix(h[0], 0xffffffffull); // column separator
    int k = begin;
    for (; k + 4 <= end; k += 4)
      for (int lane = 0; lane < 4; ++lane)
        mix(h[lane], static_cast<std::uint64_t>(inner[k + lane]));
    for (; k < end; ++k)
      mix(h[1], static_cast<std::uint64_t>(inner[k]) ^ 0x100000000ull); // tail, tagged
  }
  std::uint64_t result = h[0];
  for (int lane = 1; lane < 4; ++lane)
    mix(result, h[lane]);
  return result;
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

std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name, MatrixKind kind,
                                                 bool rank_rows) {
  SIG_VERIFY(!rank_rows || backend_named(name) == Backend::mumps,
             "a solve over several ranks (mpirun) factorizes with MUMPS: SOLVER linear=mumps, not "
                 << name);
  switch (backend_named(name)) {
  case Backend::cholmod:
    SIG_VERIFY(kind == MatrixKind::spd, "linear solver 'cholmod' factorizes spd matrices only, not "
                                            << to_string(kind) << " ones: use umfpack or mumps");
    return std::make_unique<CholmodSolver>();
  case Backend::umfpack:
    return std::make_unique<UmfpackSolver>(kind);
  case Backend::mumps:
    return std::make_unique<MumpsSolver>(kind, std::vector<int>{}, rank_rows);
  }
  return nullptr;
}

BackendTraits backend_traits(const std::string& name) {
  BackendTraits traits;
  switch (backend_named(name)) {
  case Backend::cholmod:
    traits.cholesky = true;
    traits.split_schur = true;
    break;
  case Backend::umfpack:
    break;
  case Backend::mumps:
    traits.partial_schur = true;
    break;
  }
  return traits;
}

} // namespace sig
