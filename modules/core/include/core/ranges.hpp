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
//    steps T / k, the Newton iterations of all the loops together) has one in a WorkBound.
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
/// The Newton iterations a deck may ask for: the product of its bounds (time steps or load steps,
/// SOLVER maxit, CONVEXIFICATION maxit), each of which has its own maximum in the table.
const WorkBound& max_newton_iterations();
/// "COUNT WHAT: more than the MAXIMUM a run may take (WHY)" if count > bound.maximum, else "".
std::string work_excess(const WorkBound& bound, double count);

/// Throw sig::Error "FILE: array 'ARRAY', row ROW: VALUE is not RANGE (KEYWORD FIELD=)" if
/// `value` is outside the range of KEYWORD FIELD= (rows 1-based).
void verify_in_range(double value, const std::string& keyword, const std::string& field,
                     const std::string& file, const std::string& array, std::size_t row);

/// Lengths of a case that no card states, bounded by the case's mesh (its diameter D, the
/// diagonal of its bounding box) or by the magnitudes of the deck, for the DS arrays that hold
/// them (a CONT's gaps and weights, the displacements of case.b and case.hist):
/// - a displacement component is in [-1e6 D, 1e6 D]: small strain means |u| << D, and a run
///   that moves the body a million times its size has lost its meaning (a stiffness of 1e-300,
///   a load of 1e300), while its products (energies, u^2) keep their digits;
inline constexpr double kDisplacementPerDiameter = 1e6;
ValueRange displacement_range(double diameter);
/// - a gap (distance of a node to the obstacle) is in [0, 4e30]: nodes, the obstacle's point or
///   centre and its radius are within the deck's magnitudes (1e30 a coordinate), so no node of a
///   deck lies farther than 2 sqrt(2) 1e30 + 1e30 from its obstacle;
inline constexpr double kLargestGap = 4 * kLargestMagnitude;
ValueRange gap_range();
/// - a contact weight (half of each of a node's two Gamma3 edges, times the thickness) is in
///   (0, thickness x D]: neither edge is longer than D.
ValueRange weight_range(double thickness, double diameter, int dim = 2);
/// Throw sig::Error "FILE: array 'ARRAY', row ROW: VALUE is not RANGE (WHY)" if `value` is
/// outside `range` (rows 1-based).
void verify_in_range(double value, const ValueRange& range, const std::string& file,
                     const std::string& array, std::size_t row);

} // namespace sig
