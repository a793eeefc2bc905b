#include "integrator/kelvin_voigt_scheme.hpp"

#include "core/error.hpp"

#include <cmath>

namespace sig {

QuasistaticKelvinVoigt::QuasistaticKelvinVoigt(ViscoelasticProblem problem, double k,
                                               Eigen::VectorXd u0)
    : load_(std::move(problem.load)), k_(k), rank_rows_(problem.rank_rows), u_(std::move(u0)) {
  SIG_VERIFY(k_ > 0 && std::isfinite(k_), "quasistatic march: time step k = " << k_);
  SIG_VERIFY(load_, "quasistatic march: no load history");
  const int n = problem.num_dofs();
  if (u_.size() == 0) u_ = Eigen::VectorXd::Zero(n);
  SIG_VERIFY(u_.size() == n, "quasistatic march: u0 of size " << u_.size() << " for " << n);
  S_ = k_ * problem.K;
  elastic_ = SymmetricProduct(problem.K, rank_rows_);
  if (problem.C.size() > 0) S_ += problem.C;
  // w_0 = 0 (ALGORITHMS.md C8): every history starts at P_1 = 0.
  for (const ExponentialStiffness& term : problem.memory) {
    S_ += (0.5 * k_) * term.K;
    memory_K_.emplace_back(term.K, rank_rows_);
    memory_.emplace_back(term.beta, k_, Eigen::VectorXd::Zero(n));
  }
}

Eigen::VectorXd QuasistaticKelvinVoigt::right_side(int n) const {
  Eigen::VectorXd b = load_(n * k_);
  elastic_.subtract(u_, b);
  for (std::size_t m = 0; m < memory_.size(); ++m)
    memory_K_[m].subtract(k_ * memory_[m].history(), b);
  return b;
}

void QuasistaticKelvinVoigt::accept(int, const Eigen::VectorXd& w) {
  SIG_VERIFY(w.size() == u_.size(),
             "quasistatic march: a velocity of size " << w.size() << " for " << u_.size());
  u_ += k_ * w;
  for (ExponentialMemory& memory : memory_)
    memory.advance(w);
}

} // namespace sig
