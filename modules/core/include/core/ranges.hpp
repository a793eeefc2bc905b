#pragma once
// The ranges of the datafile's numbers, stated once (src/ranges.cpp) and used by both readers:
//  - the datafile reader checks every value of a field that has a range when a stage reads it
//    (Card::real, integer, reals, integers): "deck.dat:4: field 'nu': must be in (-1, 0.5)";
//  - a DS reader checks the arrays holding the same quantities with verify_in_range, so a
//    file edited by hand or written by another program obeys the rules of the deck:
//    "case.mili: array 'poisson', row 1: 0.5 is not in (-1, 0.5) (MATERIAL nu=)".
// A new card field with a range gets one line in the table; its DS array one verify_in_range.
// Rules that tie several fields (r_in < r_out, N even) stay with the code that reads them.
//
// Two rules hold beyond the table:
//  - every real number of the deck is 0 or of a magnitude in [1e-30, 1e30] (magnitude_excess):
//    the solve forms products of a few of them (u ~ f L / E, energies f u, squared norms of
//    1e8 values), which then stay inside the doubles' range (1e-308 .. 1e308) with digits left;
//  - the work a run does is bounded: the counts that bound it (iterations, load steps, mesh
//    sizes) have a maximum in the table, with its reason, and what no one field states (the time
//    steps T / k) has one in work_bound.
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

/// The smallest and largest magnitude of a real number of the deck (0 aside), and why.
inline constexpr double kSmallestMagnitude = 1e-30;
inline constexpr double kLargestMagnitude = 1e30;
/// "" if x is 0 or kSmallestMagnitude <= |x| <= kLargestMagnitude, else why not: "1e-300 is
/// smaller than 1e-30, the smallest magnitude a number of a deck may have (0 aside): ...".
std::string magnitude_excess(double x);

/// Work that no one field bounds, with its maximum and why.
struct WorkBound {
  double maximum;
  const char* what; ///< "time steps"
  const char* why;
};
/// The time steps a march may take (TIME T / k).
const WorkBound& max_time_steps();
/// "COUNT WHAT: more than the MAXIMUM a run may take (WHY)" if count > bound.maximum, else "".
std::string work_excess(const WorkBound& bound, double count);

/// Throw sig::Error "FILE: array 'ARRAY', row ROW: VALUE is not RANGE (KEYWORD FIELD=)" if
/// `value` is outside the range of KEYWORD FIELD= (rows 1-based).
void verify_in_range(double value, const std::string& keyword, const std::string& field,
                     const std::string& file, const std::string& array, std::size_t row);

} // namespace sig
