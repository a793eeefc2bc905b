#include "solver/schur.hpp"

#include "core/error.hpp"
#include "core/log.hpp"
#include "solver/cholmod_split.hpp"
#include "solver/mpi_session.hpp"
#include "solver/mumps_solver.hpp"

#include <algorithm>
#include <cctype>

namespace sig {

namespace {

/// Columns of K_ic solved per block: wide enough for level-3 BLAS in the triangular solves,
/// narrow enough that the dense n_i x block right sides stay a few tens of megabytes.
constexpr Eigen::Index schur_block_columns = 32;

using Triplets = std::vector<Eigen::Triplet<double>>;

} // namespace

namespace detail {
class InteriorSolver {
public:
  virtual ~InteriorSolver() = default;
  virtual Eigen::MatrixXd solve(const Eigen::MatrixXd& r) const = 0;
};
} // namespace detail

namespace {

/// Any backend on the assembled K_ii.
class FactoredInterior final : public detail::InteriorSolver {
public:
  explicit FactoredInterior(std::unique_ptr<LinearSolver> solver) : solver_(std::move(solver)) {}
  Eigen::MatrixXd solve(const Eigen::MatrixXd& r) const override { return solver_->solve(r); }

private:
  std::unique_ptr<LinearSolver> solver_;
};

/// MUMPS's partial factorization of the whole K: its solves act on the interior problem and
/// return zeros on the Schur variables, so right sides are scattered into full vectors.
class MumpsInterior final : public detail::InteriorSolver {
public:
  MumpsInterior(std::unique_ptr<MumpsSolver> solver, const std::vector<int>& interior, int n)
      : solver_(std::move(solver)), interior_(interior), n_(n) {}
  Eigen::MatrixXd solve(const Eigen::MatrixXd& r) const override {
    Eigen::MatrixXd full = Eigen::MatrixXd::Zero(n_, r.cols());
    for (size_t k = 0; k < interior_.size(); ++k)
      full.row(interior_[k]) = r.row(Eigen::Index(k));
    const Eigen::MatrixXd x = solver_->solve(full);
    Eigen::MatrixXd y(r.rows(), r.cols());
    for (size_t k = 0; k < interior_.size(); ++k)
      y.row(Eigen::Index(k)) = x.row(interior_[k]);
    return y;
  }

private:
  std::unique_ptr<MumpsSolver> solver_;
  std::vector<int> interior_;
  int n_;
};

} // namespace

SchurComplement::SchurComplement(const Eigen::SparseMatrix<double>& K,
                                 std::vector<int> interface_dofs, const std::string& backend,
                                 MatrixKind kind, bool whole_positive_definite, bool rank_rows)
    : backend_(backend), interface_(std::move(interface_dofs)), rank_rows_(rank_rows) {
  std::transform(backend_.begin(), backend_.end(), backend_.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  const int n = static_cast<int>(K.rows());
  const int m = static_cast<int>(interface_.size());
  SIG_VERIFY(K.rows() == K.cols(),
             "Schur complement: K is " << K.rows() << " x " << K.cols() << ", not square");
  SIG_VERIFY(m > 0 && m < n, "Schur complement: " << m << " interface dofs for " << n
                                                  << " unknowns (need 0 < m < n)");
  SIG_VERIFY(std::is_sorted(interface_.begin(), interface_.end()) &&
                 std::adjacent_find(interface_.begin(), interface_.end()) == interface_.end(),
             "Schur complement: interface dofs must be sorted and distinct");
  SIG_VERIFY(interface_.front() >= 0 && interface_.back() < n,
             "Schur complement: interface dof out of [0, " << n << ")");
  // A rank's rows are not symmetric; the TAE's reader checked the whole.
  SIG_ASSERT(rank_rows ||
                 (Eigen::SparseMatrix<double>(K.transpose()) - K).norm() <= 1e-12 * K.norm(),
             "Schur complement of a non-symmetric K");

  // position[d] >= 0: interior index; position[d] < 0: interface index -position[d] - 1.
  std::vector<int> position(static_cast<size_t>(n), 0);
  for (int k = 0; k < m; ++k)
    position[static_cast<size_t>(interface_[k])] = -k - 1;
  interior_.reserve(static_cast<size_t>(n - m));
  for (int d = 0; d < n; ++d)
    if (position[static_cast<size_t>(d)] == 0) {
      position[static_cast<size_t>(d)] = static_cast<int>(interior_.size());
      interior_.push_back(d);
    }
  const int ni = n - m;

  // CHOLMOD: the whole factor, the interface last (cholmod_split.hpp), on a positive definite K
  //  (simplicial, the 2D march) or on rows of 3D fill (supernodal, K_cc shifted: K_ii alone need
  //  be positive definite), where the block solves below cost several factorizations.
  const BackendTraits traits = backend_traits(backend_);
  SIG_VERIFY(!rank_rows || traits.partial_schur,
             "a solve over several ranks (mpirun) factorizes with MUMPS: SOLVER linear=mumps, not "
                 << backend_);
  const bool nested = prefers_nested_dissection(K);
  if (traits.split_schur && kind == MatrixKind::spd && (whole_positive_definite || nested)) {
    try {
      const Stopwatch factor_clock;
      Eigen::SparseMatrix<double> compressed = K;
      compressed.makeCompressed();
      split_ = std::make_unique<CholmodSplitSolver>(
          compressed, interface_, nested ? SplitLayout::supernodal : SplitLayout::simplicial);
      S_ = split_->schur_complement();
      seconds_factorize_ = factor_clock.seconds();
      return;
    } catch (const Error& e) {
      // Supernodal: K_ii is not positive definite, which the interior path below reports in its
      // own words (the stage then names the part held by nothing), so no warning first.
      if (!nested || dynamic_cast<const FactorizationFailure*>(&e) == nullptr)
        log_warning(std::string("the matrix could not be factorized whole, its interface last (") +
                    e.what() + "): its interior is factorized apart");
      split_.reset();
    }
  }

  // MUMPS factorizes K itself; the other backends need K_ii apart.
  const bool split_interior = !traits.partial_schur;
  Triplets ii, ic;
  Eigen::MatrixXd K_cc = Eigen::MatrixXd::Zero(m, m);
  for (int j = 0; j < K.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, j); it; ++it) {
      const int pr = position[static_cast<size_t>(it.row())];
      const int pc = position[static_cast<size_t>(j)];
      if (pr >= 0 && pc >= 0) {
        if (split_interior) ii.emplace_back(pr, pc, it.value());
      } else if (pr >= 0)
        ic.emplace_back(pr, -pc - 1, it.value());
      else if (pc < 0)
        K_cc(-pr - 1, -pc - 1) = it.value();
    }
  K_ic_.resize(ni, m);
  K_ic_.setFromTriplets(ic.begin(), ic.end());

  if (!split_interior) {
    // One partial factorization of K gives K_ii's factor and S together.
    const Stopwatch factor_clock;
    auto mumps = std::make_unique<MumpsSolver>(kind, interface_, rank_rows);
    mumps->factorize(K);
    seconds_factorize_ = factor_clock.seconds();
    const Stopwatch schur_clock;
    S_ = mumps->schur_complement();
    mumps_ = mumps.get();
    interior_solver_ = std::make_unique<MumpsInterior>(std::move(mumps), interior_, n);
    seconds_schur_ = schur_clock.seconds();
  } else {
    const Stopwatch factor_clock;
    Eigen::SparseMatrix<double> K_ii(ni, ni);
    K_ii.setFromTriplets(ii.begin(), ii.end());
    auto solver = make_linear_solver(backend_, kind);
    solver->analyze(K_ii);
    solver->factorize(K_ii);
    interior_solver_ = std::make_unique<FactoredInterior>(std::move(solver));
    seconds_factorize_ = factor_clock.seconds();

    // S = K_cc - K_ci K_ii^{-1} K_ic, a block of columns of K_ic at a time.
    const Stopwatch schur_clock;
    S_ = K_cc;
    for (Eigen::Index j0 = 0; j0 < m; j0 += schur_block_columns) {
      const Eigen::Index w = std::min<Eigen::Index>(schur_block_columns, m - j0);
      const Eigen::MatrixXd R = Eigen::MatrixXd(K_ic_.middleCols(j0, w));
      const Eigen::MatrixXd X = interior_solver_->solve(R);
      S_.middleCols(j0, w).noalias() -= K_ic_.transpose() * X;
    }
    // Rounding leaves S unsymmetric at the 1e-16 level; contact solvers expect it exact.
    S_ = 0.5 * (S_ + S_.transpose()).eval();
    seconds_schur_ = schur_clock.seconds();
  }
}

SchurComplement::~SchurComplement() = default;

std::string SchurComplement::ordering() const {
  return mumps_ != nullptr ? mumps_->ordering() : std::string();
}

const MumpsStatistics* SchurComplement::mumps_statistics() const {
  return mumps_ != nullptr ? &mumps_->statistics() : nullptr;
}

Eigen::VectorXd SchurComplement::interior_part(const Eigen::VectorXd& v) const {
  Eigen::VectorXd p(static_cast<Eigen::Index>(interior_.size()));
  for (size_t k = 0; k < interior_.size(); ++k)
    p[Eigen::Index(k)] = v[interior_[k]];
  return p;
}

Eigen::VectorXd SchurComplement::interface_part(const Eigen::VectorXd& v) const {
  Eigen::VectorXd p(static_cast<Eigen::Index>(interface_.size()));
  for (size_t k = 0; k < interface_.size(); ++k)
    p[Eigen::Index(k)] = v[interface_[k]];
  return p;
}

Eigen::VectorXd SchurComplement::condense(const Eigen::VectorXd& f) {
  SIG_VERIFY(f.size() == size(),
             "Schur complement: load of size " << f.size() << ", expected " << size());
  if (mumps_ != nullptr || split_) {
    condensed_load_ = f;
    if (split_) {
      split_reduced_ = true;
      return split_->reduce(f);
    }
    return mumps_->reduce(f);
  }
  const Eigen::VectorXd y = interior_solver_->solve(interior_part(f)).col(0);
  return interface_part(f) - K_ic_.transpose() * y;
}

Eigen::VectorXd SchurComplement::expand(const Eigen::VectorXd& f, const Eigen::VectorXd& u_c) {
  SIG_VERIFY(f.size() == size(),
             "Schur complement: load of size " << f.size() << ", expected " << size());
  SIG_VERIFY(u_c.size() == static_cast<Eigen::Index>(interface_.size()),
             "Schur complement: interface displacement of size " << u_c.size() << ", expected "
                                                                 << interface_.size());
  if (split_) {
    // The pair of substitutions; the forward one again when this load was not the last condensed.
    if (!split_reduced_ || condensed_load_.size() != f.size() || condensed_load_ != f) {
      split_->reduce(f);
      condensed_load_ = f;
    }
    split_reduced_ = false;
    return split_->expand(u_c);
  }
  Eigen::VectorXd u(size());
  if (mumps_ != nullptr && condensed_load_.size() == f.size() && condensed_load_ == f) {
    u = mumps_->expand(u_c);
    condensed_load_.resize(0);
  } else {
    condensed_load_.resize(0); // the solve below overwrites MUMPS's reduced right-hand side
    Eigen::VectorXd K_ic_u_c = K_ic_ * u_c;
    if (rank_rows_) mpi::sum(K_ic_u_c.data(), static_cast<int>(K_ic_u_c.size()));
    const Eigen::VectorXd r = interior_part(f) - K_ic_u_c;
    const Eigen::VectorXd u_i = interior_solver_->solve(r).col(0);
    for (size_t k = 0; k < interior_.size(); ++k)
      u[interior_[k]] = u_i[Eigen::Index(k)];
  }
  for (size_t k = 0; k < interface_.size(); ++k)
    u[interface_[k]] = u_c[Eigen::Index(k)];
  return u;
}

} // namespace sig
