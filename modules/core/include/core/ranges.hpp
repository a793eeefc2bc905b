#pragma once
// The ranges of the datafile's numbers, stated once (src/ranges.cpp) and used by both readers:
//  - the datafile reader checks every value of a field that has a range when a stage reads it
//    (Card::real, integer, reals, integers): "deck.dat:4: field 'nu': must be in (-1, 0.5)";
//  - a DS reader checks the arrays holding the same quantities with verify_in_range, so a
//    file edited by hand or written by another program obeys the rules of the deck:
//    "case.mili: array 'poisson', row 1: 0.5 is not in (-1, 0.5) (MATERIAL nu=)".
// A new card field with a range gets one line in the table; its DS array one verify_in_range.
// Rules that tie several fields (r_in < r_out, N even) stay with the code that reads them.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace sig {

struct ValueRange {
  double low, high;
  bool low_open, high_open;
  const char* why; ///< appended to the message, or nullptr

  bool contains(double x) const;
  std::string text() const; ///< "> 0", ">= 1", "in (-1, 0.5)", "in [1, 1e+08]"
};

/// The range of `field` of card `keyword` (case-insensitive), or nullptr if any value goes.
const ValueRange* field_range(const std::string& keyword, const std::string& field);

/// (keyword, field) of every line of the table, as written there.
std::vector<std::pair<std::string, std::string>> fields_with_ranges();

/// Throw sig::Error "FILE: array 'ARRAY', row ROW: VALUE is not RANGE (KEYWORD FIELD=)" if
/// `value` is outside the range of KEYWORD FIELD= (rows 1-based).
void verify_in_range(double value, const std::string& keyword, const std::string& field,
                     const std::string& file, const std::string& array, std::size_t row);

} // namespace sig
