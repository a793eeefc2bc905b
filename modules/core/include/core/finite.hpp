#pragma once
// No NaN or inf leaves a stage: DS arrays are checked by write_ds and Ds::reals (core/ds.hpp);
// what a stage writes elsewhere (VTK fields, CSV columns, energies) is checked with this before
// the file is written.
#include <span>
#include <string>

namespace sig {

/// "value 3 of 10 is NaN" for the first value that is not finite, or "" if all are.
std::string first_non_finite(std::span<const double> values);

} // namespace sig
