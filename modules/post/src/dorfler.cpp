#include "post/dorfler.hpp"

#include "core/error.hpp"

#include <algorithm>
#include <numeric>

namespace sig {

std::vector<int> dorfler_marking(const std::vector<double>& eta, double theta) {
  SIG_VERIFY(theta > 0 && theta <= 1, "Dörfler marking: theta = " << theta << " is not in (0, 1]");
  double total = 0;
  for (std::size_t t = 0; t < eta.size(); ++t) {
    SIG_VERIFY(eta[t] >= 0, "Dörfler marking: indicator " << eta[t] << " of triangle " << t + 1
                                                          << " is negative");
    total += eta[t] * eta[t];
  }
  if (total == 0) return {}; // no error estimated: nothing to refine
  std::vector<int> order(eta.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return eta[a] > eta[b]; });
  std::vector<int> marked;
  double sum = 0;
  for (int t : order) {
    if (sum >= theta * total && !marked.empty()) break;
    marked.push_back(t);
    sum += eta[t] * eta[t];
  }
  return marked;
}

} // namespace sig
