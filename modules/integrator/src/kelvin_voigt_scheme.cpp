#include "integrator/kelvin_voigt_scheme.hpp"

#include "core/error.hpp"

#include <cmath>

namespace sig {

QuasistaticKelvinVoigt::QuasistaticKelvinVoigt(ViscoelasticProblem problem, double k,
                                               Eigen::VectorXd u0)
    : load_(std::move(problem.load)), k_(k), u_(std::move(u0)) {
  SIG_VERIFY(k_ > 0 && std::isfinite(k_), "quasistatic march: time step k = " << k_);
  SIG_VERIFY(load_, "quasistatic march: no load history");
  const int n = problem.num_dofs();
  if (u_.size() == 0) u_ = Eigen::VectorXd::Zero(n);
  SIG_VERIFY(u_.size() == n, "quasistatic march: u0 of size " << u_.size() << " for " << n);
  S_ = k_ * problem.K;
  // The right side's products read the lower triangles only: half the memory traffic.
  elastic_lower_ = problem.K.triangularView<Eigen::Lower>();
  if (problem.C.size() > 0) S_ += problem.C;
  // w_0 = 0 (ALGORITHMS.md C8): every history starts at P_1 = 0.
  for (const ExponentialStiffness& term : problem.memory) {
    S_ += (0.5 * k_) * term.K;
    memory_lower_.push_back(term.K.triangularView<Eigen::Lower>());
    memory_.emplace_back(term.beta, k_, Eigen::VectorXd::Zero(n));
  }
}

Eigen::VectorXd QuasistaticKelvinVoigt::right_side(int n) const {
  Eigen::VectorXd b = load_(n * k_);
  b.noalias() -= elastic_lower_.selfadjointView<Eigen::Lower>() * u_;
  for (std::size_t m = 0; m < memory_.size(); ++m)
    b.noalias() -= memory_lower_[m].selfadjointView<Eigen::Lower>() * (k_ * memory_[m].history());
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
