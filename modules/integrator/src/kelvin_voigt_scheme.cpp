#include "integrator/kelvin_voigt_scheme.hpp"

#include "assembly/system.hpp"
#include "core/error.hpp"

#include <cmath>

namespace sig {

QuasistaticKelvinVoigt::QuasistaticKelvinVoigt(const LinearSystem& system, ReducedSystem reduced,
                                               double k, Eigen::VectorXd u0)
    : reduced_(std::move(reduced)), k_(k), u_(std::move(u0)) {
  SIG_VERIFY(k_ > 0 && std::isfinite(k_), "quasistatic march: time step k = " << k_);
  const int n = reduced_.num_free();
  if (u_.size() == 0) u_ = Eigen::VectorXd::Zero(n);
  SIG_VERIFY(u_.size() == n, "quasistatic march: u0 of size " << u_.size() << " for " << n);
  if (reduced_.time_loads.moving.empty()) {
    rate_ = reduced_.time_loads.rate.size() > 0 ? reduced_.restrict(reduced_.time_loads.rate)
                                                : Eigen::VectorXd::Zero(n);
  }
  S_ = k_ * reduced_.K;
  // The right side's products read the lower triangles only: half the memory traffic.
  elastic_lower_ = reduced_.K.triangularView<Eigen::Lower>();
  if (system.V.size() > 0) S_ += reduced_.restrict_matrix(system.V);
  // w_0 = 0 (ALGORITHMS.md C8): every history starts at P_1 = 0.
  for (const MemoryStiffness& term : system.memory) {
    const Eigen::SparseMatrix<double> K_m = reduced_.restrict_matrix(term.K);
    S_ += (0.5 * k_) * K_m;
    memory_lower_.push_back(K_m.triangularView<Eigen::Lower>());
    memory_.emplace_back(term.beta, k_, Eigen::VectorXd::Zero(n));
  }
}

Eigen::VectorXd QuasistaticKelvinVoigt::right_side(int n) const {
  Eigen::VectorXd b =
      rate_.size() > 0 ? Eigen::VectorXd(reduced_.f + (n * k_) * rate_) : reduced_.load_at(n * k_);
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
