#include "core/finite.hpp"

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

} // namespace sig
