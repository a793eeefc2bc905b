#include "integrator/memory.hpp"

#include "core/error.hpp"

#include <cmath>

namespace sig {

ExponentialMemory::ExponentialMemory(double beta, double k, const Eigen::VectorXd& w0)
    : beta_(beta), decay_(std::exp(-beta * k)), history_(0.5 * std::exp(-beta * k) * w0) {
  SIG_VERIFY(beta > 0 && std::isfinite(beta), "memory: beta = " << beta << " must be > 0");
  SIG_VERIFY(k > 0 && std::isfinite(k), "memory: time step k = " << k << " must be > 0");
}

void ExponentialMemory::advance(const Eigen::VectorXd& w_n) {
  SIG_VERIFY(w_n.size() == history_.size(),
             "memory: a value of size " << w_n.size() << " for a history of " << history_.size());
  history_ += w_n;
  history_ *= decay_;
}

Eigen::VectorXd trapezoidal_memory(const std::function<double(double)>& kernel, double k,
                                   const std::vector<Eigen::VectorXd>& w) {
  SIG_VERIFY(!w.empty(), "memory: no values (w_0 at least)");
  const std::size_t n = w.size() - 1;
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(w.front().size());
  if (n == 0) return sum;
  const double t_n = static_cast<double>(n) * k;
  for (std::size_t j = 0; j <= n; ++j) {
    const double weight = j == 0 || j == n ? 0.5 : 1.0;
    sum += weight * kernel(t_n - static_cast<double>(j) * k) * w[j];
  }
  return k * sum;
}

} // namespace sig
