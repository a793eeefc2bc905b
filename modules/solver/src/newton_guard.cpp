// The globalization's bookkeeping (newton_guard.hpp).
#include "solver/newton_guard.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <cmath>

namespace sig {

std::string name(NewtonFailure failure) {
  switch (failure) {
  case NewtonFailure::none:
    return "none";
  case NewtonFailure::cycling:
    return "cycling";
  case NewtonFailure::stagnation:
    return "stagnation";
  case NewtonFailure::divergence:
    return "divergence";
  case NewtonFailure::drift:
    return "drift";
  case NewtonFailure::iteration_limit:
    return "iteration-limit";
  case NewtonFailure::singular_step:
    return "singular-step";
  }
  return "unknown";
}

MeritMemory::MeritMemory(int window) : window_(window) {
  SIG_VERIFY(window >= 1, "merit memory of " << window << " iterates");
}

void MeritMemory::push(double residual) {
  residuals_.push_back(residual);
  while (static_cast<int>(residuals_.size()) > window_)
    residuals_.pop_front();
}

double MeritMemory::reference() const {
  SIG_VERIFY(!residuals_.empty(), "merit memory: no iterate yet");
  return *std::max_element(residuals_.begin(), residuals_.end());
}

bool sufficient_decrease(double trial, double reference, double current, double alpha) {
  return trial * trial <= reference * reference - 2 * kArmijo * alpha * current * current;
}

bool rate_repays(double now, double before, double start) {
  const double rate = now / std::max(before, 1e-300);
  return rate < 1 && sufficient_decrease(now * std::pow(rate, kWatchSteps), start, start, 1.0);
}

CycleGuard::CycleGuard(int window) : window_(window) {}

namespace {

std::uint64_t hash_of(const std::vector<KernelBranch>& branch) {
  std::uint64_t h = 1469598103934665603ull; // FNV-1a
  for (const KernelBranch& b : branch) {
    const unsigned code = (b.wall ? 1u : 0u) | (b.stick ? 2u : 0u) | (unsigned(b.slip + 1) << 2);
    h = (h ^ code) * 1099511628211ull;
  }
  return h;
}

} // namespace

bool CycleGuard::repeats(const std::vector<KernelBranch>& branch, double residual) {
  const std::uint64_t h = hash_of(branch);
  bool cycle = false;
  // A period of one (the branches of the last iteration again) is Newton's own repeat on a
  // settled branch set, not a cycle.
  for (std::size_t i = 0; i + 1 < visits_.size(); ++i)
    if (const Visit& v = visits_[i];
        v.hash == h && v.branch == branch &&
        std::min(v.lowest_since, residual) > (1 - kProgress) * v.residual)
      cycle = true;
  for (Visit& v : visits_)
    v.lowest_since = std::min(v.lowest_since, residual);
  visits_.push_back({h, branch, residual, residual});
  while (static_cast<int>(visits_.size()) > window_)
    visits_.pop_front();
  return cycle;
}

void Damping::after_step(double alpha, double ratio) {
  if (alpha < kShortStep && ratio > kStall) {
    mu_ = std::max(kFirst, kGrowth * mu_);
  } else {
    mu_ /= kGrowth;
    if (mu_ < kFirst) mu_ = 0;
  }
}

} // namespace sig
