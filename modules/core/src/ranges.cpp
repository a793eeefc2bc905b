#include "core/ranges.hpp"

#include "core/error.hpp"
#include "text_case.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace sig {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
// Counts that size arrays: beyond this a mesh or a history no longer fits in memory, and
// indices leave the range of int (the error then says so instead of std::bad_alloc).
constexpr double max_count = 1e8;

constexpr ValueRange positive{0, inf, true, false, nullptr};
constexpr ValueRange non_negative{0, inf, false, false, nullptr};
constexpr ValueRange count_from_1{1, max_count, false, false, nullptr};
constexpr ValueRange reference{1, 2147483647, false, false, nullptr};
// Iterations of one nonlinear solve: the most a scene takes is 1445 (projection with c = 1e2 on
// the ring of scene 7b, in 14 load steps); a method that has not converged in 7x that will not.
constexpr ValueRange iterations{1, 1e4, false, false,
                                "a method that has not converged in 1e4 iterations will not: "
                                "the most any scene takes is 1445"};
// A relative test below 1e-14 (about 50 round-offs of a double) is met by chance only: the run
// would go on to maxit.
constexpr ValueRange tolerance{1e-14, 1, false, true,
                               "the test is relative: below 1e-14, some 50 round-offs, it is met "
                               "by chance only"};
constexpr ValueRange poisson{-1, 0.5, true, true,
                             "0.5 is the incompressible limit, where Hooke's law has no D"};

struct FieldRange {
  const char* keyword;
  const char* field;
  ValueRange range;
};

// One line per field with a range; fields not listed take any finite number. The contact laws'
// parameters (cn, c3, g, mu, threshold) have theirs in contact/laws (law_problem), which the
// CONTACT and FRICTION cards and the CONT reader share.
constexpr FieldRange table[] = {
    {"MESH", "R", positive},
    {"MESH", "N", {4, max_count, false, false, nullptr}},
    {"MESH", "r_in", positive},
    {"MESH", "r_out", positive},
    {"MESH", "layers", {2, max_count, false, false, nullptr}},
    {"MESH", "lx", positive},
    {"MESH", "ly", positive},
    {"MESH", "lz", positive},
    {"MESH", "L", positive},
    {"MESH", "h", positive},
    {"MESH", "nx", count_from_1},
    {"MESH", "ny", count_from_1},
    {"MESH", "refs", reference},
    {"MESH", "grading", non_negative},
    {"MESH", "cap", positive},
    {"MATERIAL", "region", reference},
    {"MATERIAL", "E", positive},
    {"MATERIAL", "nu", poisson},
    {"MATERIAL", "c1", positive},
    {"MATERIAL", "c2", non_negative},
    {"MATERIAL", "a", non_negative},
    {"MATERIAL", "thickness", positive},
    {"MATERIAL", "rho", non_negative},
    {"MEMORY", "E", positive},
    {"MEMORY", "nu", poisson},
    {"DIRICHLET", "ref", reference},
    {"TRACTION", "ref", reference},
    {"PRESSURE", "ref", reference},
    {"BODYFORCE", "region", reference},
    {"CONTACT", "ref", reference},
    {"CONTACT", "radius", positive},
    {"CONTACT", "r", positive},
    {"FRICTION", "ref", reference},
    {"SOLVER", "r", positive},
    {"SOLVER", "gamma", positive},
    {"SOLVER", "c", positive},
    {"SOLVER", "candidate_gap", positive},
    {"SOLVER", "eps", tolerance},
    {"SOLVER", "maxit", iterations},
    {"CONVEXIFICATION", "eps", tolerance},
    {"CONVEXIFICATION", "maxit", iterations},
    {"CONVEXIFICATION", "relaxation", {0, 1, true, false, nullptr}},
    // Each load step is a whole Newton solve; scene 7b takes 14.
    {"LOADSTEPS",
     "n",
     {1, 1e4, false, false, "each load step is a Newton solve of its own; scene 7b takes 14"}},
    {"TIME", "T", positive},
    {"TIME", "k", positive},
    {"TIME", "output_every", count_from_1},
    {"INITIAL", "region", reference},
    {"COMPARE", "R", positive},
    {"COMPARE", "f", positive},
};

std::string number(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

} // namespace

std::string magnitude_excess(double x) {
  const double size = std::abs(x);
  if (x == 0 || (size >= kSmallestMagnitude && size <= kLargestMagnitude)) return "";
  const bool small = size < kSmallestMagnitude;
  return number(x) + " is " + (small ? "smaller in magnitude than " : "larger in magnitude than ") +
         number(small ? kSmallestMagnitude : kLargestMagnitude) + ", the " +
         (small ? "smallest" : "largest") +
         " magnitude a number of a deck may have (0 aside): beyond it the products the solve "
         "forms (u ~ f L / E, energies, squared norms) leave the range of doubles or lose their "
         "digits";
}

const WorkBound& max_time_steps() {
  // Scene 8b's march takes 3000 steps in 15 s; 1e6 steps of that mesh would take over an hour.
  static const WorkBound bound{1e6, "time steps",
                               "each step is at least one solve; scene 8b takes 3000"};
  return bound;
}

const WorkBound& max_newton_iterations() {
  // Each field's maximum alone lets the loops multiply to 1e8 (maxit x CONVEXIFICATION maxit,
  // LOADSTEPS n x maxit) or 1e10 (1e6 time steps x maxit); at a millisecond an iteration on the
  // smallest meshes, 1e7 is hours.
  static const WorkBound bound{1e7, "Newton iterations",
                               "the most a scene deck asks for is 5.1e6: scene 6's stability "
                               "map at k = 1/512, 512 time steps x SOLVER maxit 50 x "
                               "CONVEXIFICATION maxit 200"};
  return bound;
}

std::string work_excess(const WorkBound& bound, double count) {
  if (count <= bound.maximum) return "";
  return number(count) + " " + bound.what + ": more than the " + number(bound.maximum) +
         " a run may take (" + bound.why + ")";
}

bool ValueRange::contains(double x) const {
  return (low_open ? x > low : x >= low) && (high_open ? x < high : x <= high);
}

std::string ValueRange::text() const {
  if (high == inf) return (low_open ? "> " : ">= ") + number(low);
  return "in " + std::string(low_open ? "(" : "[") + number(low) + ", " + number(high) +
         (high_open ? ")" : "]");
}

const ValueRange* field_range(const std::string& keyword, const std::string& field) {
  const std::string key = to_upper(keyword), name = to_lower(field);
  for (const FieldRange& f : table)
    if (key == f.keyword && name == to_lower(f.field)) return &f.range;
  return nullptr;
}

std::vector<std::pair<std::string, std::string>> fields_with_ranges() {
  std::vector<std::pair<std::string, std::string>> fields;
  for (const FieldRange& f : table)
    fields.emplace_back(f.keyword, f.field);
  return fields;
}

void verify_in_range(double value, const std::string& keyword, const std::string& field,
                     const std::string& file, const std::string& array, std::size_t row) {
  const ValueRange* range = field_range(keyword, field);
  SIG_VERIFY(range != nullptr, "verify_in_range: " << keyword << " " << field << " has no range");
  SIG_VERIFY(std::isfinite(value) && range->contains(value),
             file << ": array '" << array << "', row " << row << ": " << value << " is not "
                  << range->text() << " (the range of " << keyword << " " << field << "=)");
  const std::string excess = magnitude_excess(value);
  SIG_VERIFY(excess.empty(), file << ": array '" << array << "', row " << row << ": " << excess
                                  << " (" << keyword << " " << field << "=)");
}

ValueRange displacement_range(double diameter) {
  const double bound = kDisplacementPerDiameter * diameter;
  return {-bound, bound, false, false,
          "a displacement is at most 1e6 times the mesh's diameter: small strain means |u| much "
          "smaller than the body, and beyond that a stiffness or a load is out of scale"};
}

ValueRange gap_range() {
  return {0, kLargestGap, false, false,
          "a gap is the distance of a node to the obstacle, both within the deck's magnitudes "
          "(1e30 a coordinate)"};
}

ValueRange weight_range(double thickness, double diameter, int dim) {
  if (dim == 3)
    return {0, diameter * diameter, true, false,
            "a weight is a third of a node's contact faces, together smaller than the square of "
            "the mesh's diameter"};
  return {0, thickness * diameter, true, false,
          "a weight is half of a node's two contact edges, each no longer than the mesh's "
          "diameter, times the thickness"};
}

void verify_in_range(double value, const ValueRange& range, const std::string& file,
                     const std::string& array, std::size_t row) {
  SIG_VERIFY(std::isfinite(value) && range.contains(value),
             file << ": array '" << array << "', row " << row << ": " << value << " is not "
                  << range.text() << (range.why ? std::string(" (") + range.why + ")" : ""));
}

} // namespace sig
