#pragma once
// Reading a numeric DS array whatever its stored type: stages store counts and codes as Int64
// and measures as Float64, and post-processing only needs the numbers.
#include "core/ds.hpp"

#include <vector>

namespace sig {

inline std::vector<double> numbers(const Ds& ds, const std::string& name) {
  for (const auto& array : ds.arrays()) {
    if (array.name == name && array.type == DsType::Int64) {
      const auto ints = ds.ints(name);
      return {ints.begin(), ints.end()};
    }
  }
  return ds.reals(name); // also the error naming the file when the array is missing
}

} // namespace sig
