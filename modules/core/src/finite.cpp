#include "core/finite.hpp"

#include "core/error.hpp"

#include <cmath>

namespace sig {

std::string first_non_finite(std::span<const double> values) {
  for (std::size_t k = 0; k < values.size(); ++k)
    if (!std::isfinite(values[k]))
      return "value " + std::to_string(k + 1) + " of " + std::to_string(values.size()) + " is " +
             (std::isnan(values[k]) ? "NaN"
              : values[k] > 0       ? "inf"
                                    : "-inf");
  return "";
}

void verify_finite(std::span<const double> values, const std::string& file,
                   const std::string& name) {
  const std::string bad = first_non_finite(values);
  SIG_VERIFY(bad.empty(), file << ": array '" << name << "': " << bad);
}

} // namespace sig
