// The condensation of a linear bulk onto its contact components (contact_condensation.hpp).
#include "solver/contact_condensation.hpp"

#include "core/error.hpp"
#include "core/log.hpp"
#include "solver/mpi_session.hpp"
#include "solver/nodal_frames.hpp"
#include "solver/schur.hpp"

#include <algorithm>

namespace sig {

namespace {

/// Position of `dof` in the sorted `interface`.
int position_in(const std::vector<int>& interface, int dof) {
  return static_cast<int>(std::lower_bound(interface.begin(), interface.end(), dof) -
                          interface.begin());
}

} // namespace

ContactCondensation::ContactCondensation(Eigen::SparseMatrix<double> K, std::vector<int> first_dofs,
                                         std::vector<ContactFrame> frames, bool tangential,
                                         const std::string& backend, bool positive_definite,
                                         bool rank_rows)
    : K_(std::move(K)), frames_of_nodes_(std::move(frames)), first_(std::move(first_dofs)),
      rank_rows_(rank_rows) {
  const int m = static_cast<int>(first_.size());
  SIG_VERIFY(static_cast<int>(frames_of_nodes_.size()) == m,
             "contact condensation: " << frames_of_nodes_.size() << " frames for " << m
                                      << " nodes");
  d_ = m > 0 ? static_cast<int>(frames_of_nodes_.front().rows()) : 2;
  for (const ContactFrame& R : frames_of_nodes_)
    SIG_VERIFY(R.rows() == d_ && R.cols() == d_, "contact condensation: frames of different sizes");
  // 1. Nodal frames, so each normal displacement and slip is one unknown; applied in place, K
  //    keeps its pattern.
  const Stopwatch clock;
  K_.makeCompressed();
  frames_ = std::make_unique<FrameRotation>(K_, first_, d_);
  frames_->rotate(K_, frames_of_nodes_);

  // 2. The Schur complement onto the normal unknowns (and the slips with friction): one sparse
  //    factorization of the rest, the body with Gamma3 held, positive definite even when K is
  //    not. The normal unknown is the frame's last component, the slip its d - 1 first (t, or
  //    t1 and t2).
  for (int p = 0; p < m; ++p) {
    interface_.push_back(first_[p] + d_ - 1);
    if (tangential)
      for (int k = 0; k < d_ - 1; ++k)
        interface_.push_back(first_[p] + k);
  }
  std::sort(interface_.begin(), interface_.end());
  SIG_VERIFY(std::adjacent_find(interface_.begin(), interface_.end()) == interface_.end(),
             "a node appears in two contact elements");
  for (int p = 0; p < m; ++p) {
    normal_dof_.push_back(position_in(interface_, first_[p] + d_ - 1));
    if (tangential)
      for (int k = 0; k < d_ - 1; ++k)
        tangential_dof_.push_back(position_in(interface_, first_[p] + k));
  }
  try {
    schur_ = std::make_unique<SchurComplement>(K_, interface_, backend, MatrixKind::spd,
                                               positive_definite, rank_rows);
  } catch (const FactorizationFailure& e) {
    // With the contact components held the rest of the body must be fixed, whatever the method:
    // the stage names the part that is not (assembly/singular_matrix.hpp).
    throw FactorizationFailure(std::string("the body with its contact nodes held cannot be "
                                           "factorized: ") +
                               e.what());
  }
  seconds_frames_ = clock.seconds() - schur_->seconds_factorize() - schur_->seconds_schur();
}

ContactCondensation::~ContactCondensation() = default;

double ContactCondensation::seconds_factorize() const {
  return schur_->seconds_factorize();
}

double ContactCondensation::seconds_schur() const {
  return schur_->seconds_schur();
}

std::string ContactCondensation::ordering() const {
  return schur_->ordering();
}

const Eigen::MatrixXd& ContactCondensation::schur() const {
  return schur_->matrix();
}

const MumpsStatistics* ContactCondensation::mumps_statistics() const {
  return schur_->mumps_statistics();
}

CondensedProblem ContactCondensation::problem(const Eigen::VectorXd& f) {
  CondensedProblem problem;
  problem.S = schur();
  problem.f = condense(f);
  problem.gap = Eigen::VectorXd::Zero(contacts());
  problem.normal_dof = normal_dof_;
  problem.tangential_dof = tangential_dof_;
  problem.regularization = kRelativeRegularization * problem.S.diagonal().cwiseAbs().maxCoeff();
  return problem;
}

Eigen::VectorXd ContactCondensation::condense(const Eigen::VectorXd& f) {
  SIG_VERIFY(f.size() == K_.rows(),
             "contact condensation: a load of size " << f.size() << " for " << K_.rows());
  load_ = f;
  frames_->to_frames(load_, frames_of_nodes_);
  return schur_->condense(load_);
}

Eigen::VectorXd ContactCondensation::expand(const Eigen::VectorXd& w) {
  SIG_VERIFY(load_.size() == K_.rows(), "contact condensation: expand() before any condense()");
  Eigen::VectorXd u = schur_->expand(load_, w);
  frames_->from_frames(u, frames_of_nodes_);
  return u;
}

Eigen::VectorXd ContactCondensation::restrict(const Eigen::VectorXd& u) const {
  SIG_VERIFY(u.size() == K_.rows(),
             "contact condensation: a vector of size " << u.size() << " for " << K_.rows());
  Eigen::VectorXd framed = u;
  frames_->to_frames(framed, frames_of_nodes_);
  Eigen::VectorXd w(static_cast<Eigen::Index>(interface_.size()));
  for (std::size_t k = 0; k < interface_.size(); ++k)
    w[static_cast<Eigen::Index>(k)] = framed[interface_[k]];
  return w;
}

double ContactCondensation::relative_residual(const Eigen::VectorXd& u, const Eigen::VectorXd& N,
                                              const Eigen::VectorXd& T) const {
  SIG_VERIFY(load_.size() == K_.rows(), "contact condensation: no load condensed yet");
  Eigen::VectorXd framed = u;
  frames_->to_frames(framed, frames_of_nodes_);
  Eigen::VectorXd r = K_ * framed;
  if (rank_rows_) mpi::sum(r.data(), static_cast<int>(r.size())); // each rank's rows of K u
  r -= load_;
  for (int p = 0; p < contacts(); ++p) {
    r[first_[p] + d_ - 1] += N[p];
    if (tangential())
      for (int k = 0; k < d_ - 1; ++k)
        r[first_[p] + k] += T[(d_ - 1) * p + k];
  }
  return r.norm() / std::max(load_.norm(), 1e-300);
}

} // namespace sig
