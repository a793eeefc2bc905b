#include "mesh/mesh_card.hpp"

#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/ranges.hpp"
#include "mesh/freefem.hpp"
#include "mesh/generators.hpp"
#include "mesh/gmsh.hpp"
#include "mesh/nopo.hpp"
#include "mesh/topology.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

namespace sig {
namespace {

/// Fields each generator reads; any other field on the card is an error.
const std::set<std::string>& fields_of(const std::string& generator) {
  static const std::map<std::string, std::set<std::string>> fields = {
      {"half_disc", {"r", "n", "grading"}},
      {"disc", {"centre", "center", "r", "n", "grading", "arcs"}},
      {"ring",
       {"centre", "center", "r_in", "r_out", "n", "layers", "gamma1_above", "gamma3_below"}},
      {"rectangle", {"lx", "ly", "nx", "ny", "refs", "pattern"}},
      {"square", {"lx", "nx", "refs", "pattern"}},
      {"box", {"lx", "ly", "lz", "h"}},
      {"half_ball", {"r", "h", "grading", "cap"}},
      {"ball", {"centre", "center", "r", "h"}},
      {"cylinder", {"r", "l", "h"}},
      {"file", {"coincident"}},
  };
  return fields.at(generator);
}

// Lengths > 0, counts >= 1 (N >= 4, layers >= 2), grading >= 0 are the card's ranges
// (core/ranges.hpp), checked by Card::real and Card::integer.

int even_count(const Card& card, const std::string& name, int multiple) {
  const int value = static_cast<int>(card.integer(name));
  if (value % multiple != 0)
    card.fail(name, multiple == 2
                        ? std::string("must be even and >= 4")
                        : "must be a multiple of " + std::to_string(multiple) + " and >= 4");
  return value;
}

// The nodes a generator would make, checked before it allocates them (nx=ny=100000 is 1e10).
void verify_size(const Card& card, const std::string& field, double nodes) {
  if (nodes > max_mesh_nodes) {
    std::ostringstream what;
    what << "the mesh would have about " << nodes << " nodes, more than the " << max_mesh_nodes
         << " a mesh may have";
    card.fail(field, what.str());
  }
}

// The shape a generator would make within the deck's magnitudes (core/ranges.hpp), checked before
// it is meshed so that the error names the field that made it, not generator=: `span` is the
// diagonal of the shape's bounding box, made by `field`.
void verify_span(const Card& card, const std::string& field, double span) {
  if (const std::string excess = magnitude_excess(span); !excess.empty()) {
    std::ostringstream what;
    what << "the mesh would span " << span << " (the diagonal of its bounding box): " << excess;
    card.fail(field, what.str());
  }
}

// centre= as CONTACT and INITIAL spell it; center= is its old spelling, read alike. A 3D shape
// (dim = 3) takes three coordinates, the origin when the card gives none (the schema's default
// is the plane's 0,0).
Point centre(const Card& card, int dim) {
  if (card.has("centre") && card.has("center"))
    card.fail("center", "give the centre once: centre= (center= is its old spelling)");
  if (dim == 3 && !card.has("centre") && !card.has("center")) return Point(0, 0, 0);
  const char* field = card.has("center") ? "center" : "centre";
  const std::vector<double> c = card.reals(field);
  if (static_cast<int>(c.size()) != dim)
    card.fail(field, dim == 3 ? std::string("expects three coordinates, e.g. ") + field + "=0,0,10"
                              : std::string("expects two coordinates, e.g. ") + field + "=0,10");
  return dim == 3 ? Point(c[0], c[1], c[2]) : Point(c[0], c[1]);
}

// The centre of a shape of `radius` whose nodes stay within the deck's magnitudes (a centre of
// 1e30 put the disc's nodes beyond them, blamed on generator=).
Point centre_within(const Card& card, double radius, int dim = 2) {
  const Point c = centre(card, dim);
  const double farthest = c.cwiseAbs().maxCoeff() + radius;
  if (const std::string excess = magnitude_excess(farthest); !excess.empty()) {
    std::ostringstream what;
    what << "a node would lie at a coordinate of " << farthest << " (the centre's plus the radius "
         << radius << "): " << excess;
    card.fail(card.has("center") ? "center" : "centre", what.str());
  }
  return c;
}

std::array<int, 4> refs(const Card& card) {
  const std::vector<long> r = card.integers("refs");
  if (r.size() != 4 || *std::min_element(r.begin(), r.end()) < 1)
    card.fail("refs", "expects four references >= 1: bottom, right, top, left");
  return {static_cast<int>(r[0]), static_cast<int>(r[1]), static_cast<int>(r[2]),
          static_cast<int>(r[3])};
}

Mesh mesh_from_file(const Card& card, const std::filesystem::path& folder) {
  const std::filesystem::path path = folder / card.text("file");
  const std::string extension = path.extension().string();
  if (extension != ".nopo" && extension != ".msh")
    card.fail("file", "unknown mesh file extension '" + extension + "' (.nopo or .msh)");
  if (const std::string why = not_a_regular_file(path); !why.empty())
    card.fail("file", "cannot read " + path.string() + ": " + why);
  if (!std::ifstream(path)) card.fail("file", "cannot read " + path.string());
  Mesh mesh = read_mesh_file(path);
  // Two nodes at one place that the triangles do not share leave an open crack: what the file
  // meant is rarely that (gmsh without Coherence, meshes pasted together).
  const auto pairs = coincident_nodes(mesh);
  if (!pairs.empty()) {
    std::vector<long> numbers;
    for (const auto& [a, b] : pairs) {
      numbers.push_back(a + 1);
      numbers.push_back(b + 1);
    }
    std::ostringstream what;
    what << path.string() << ": " << pairs.size() << " pair(s) of nodes at the same place (nodes "
         << pairs.front().first + 1 << " and " << pairs.front().second + 1 << " at ("
         << mesh.nodes[pairs.front().first].x() << ", " << mesh.nodes[pairs.front().first].y()
         << ")): an open crack in the mesh";
    if (card.choice("coincident", {"error", "allow"}) == "error")
      card.fail("file", what.str() + "; merge the nodes, or give coincident=allow if the crack "
                                     "is meant");
    warn_entities(path.string(), "coincident node(s) (1-based, in pairs)", numbers,
                  "kept apart (coincident=allow: an open crack)");
  }
  return mesh;
}

// About one node per s^3 at mesh size s: the half ball graded from its pole (s = h + grading d,
// capped) has at most the integral of 2 pi d^2 / s(d)^3 over the distance d to the pole (a
// hemisphere of radius d holds the shell), 1.2-1.8x the nodes gmsh makes at R = 8.
double graded_ball_nodes(double R, double h, double grading, double cap) {
  const double largest = std::max(cap > 0 ? cap : R / 4, h);
  const double reach = std::numbers::sqrt2 * R;
  const int steps = 1000;
  double nodes = 0;
  for (int i = 0; i < steps; ++i) {
    const double d = (i + 0.5) * reach / steps;
    nodes += 2 * std::numbers::pi * d * d / std::pow(std::min(h + grading * d, largest), 3);
  }
  return nodes * reach / steps;
}

Mesh generate(const Card& card, const std::string& generator) {
  if (generator == "ball") {
    const double r = card.real("R"), h = card.real("h");
    verify_span(card, "R", 2 * std::sqrt(3.0) * r);
    verify_size(card, "h", 4.2 * std::pow(r / h + 1, 3));
    return ball(centre_within(card, r, 3), r, h);
  }
  if (generator == "cylinder") {
    const double r = card.real("R"), l = card.real("L"), h = card.real("h");
    verify_span(card, "R", std::sqrt(8 * r * r + l * l));
    verify_size(card, "h", 3.2 * std::pow(r / h + 1, 2) * (l / h + 1));
    return cylinder(r, l, h);
  }
  if (generator == "box" || generator == "half_ball") {
    // About 6 / h^3 tetrahedra and 1 / h^3 nodes per unit volume (gmsh's Delaunay).
    const double h = card.real("h");
    if (generator == "box") {
      const double lx = card.real("lx"), ly = card.real("ly"), lz = card.real("lz");
      verify_span(card, "lx", std::sqrt(lx * lx + ly * ly + lz * lz));
      verify_size(card, "h", (lx / h + 1) * (ly / h + 1) * (lz / h + 1));
      return box(lx, ly, lz, h);
    }
    const double r = card.real("R"), grading = card.real("grading");
    const double cap = card.has("cap") ? card.real("cap") : 0;
    verify_span(card, "R", 3 * r);
    verify_size(card, "h",
                grading > 0 ? graded_ball_nodes(r, h, grading, cap) : 2.1 * std::pow(r / h + 1, 3));
    return half_ball(r, h, grading, cap);
  }
  if (generator == "half_disc" || generator == "disc") {
    const double r = card.real("R");
    // The disc's box is 2R x 2R, the half disc's 2R x R.
    verify_span(card, "R", (generator == "disc" ? 2 * std::numbers::sqrt2 : std::sqrt(5.0)) * r);
    const int n = even_count(card, "N", generator == "disc" ? 4 : 2);
    // Uniform at the arc's size h = 2 pi R / N (disc) or pi R / N: N^2 / (4 pi) nodes at most.
    verify_size(card, "N", static_cast<double>(n) * n / (4 * std::numbers::pi));
    const double grading = card.real("grading");
    return generator == "disc"
               ? disc(centre_within(card, r), r, n, grading,
                      card.choice("arcs", {"uniform", "graded"}, "uniform") == "graded")
               : half_disc(r, n, grading);
  }
  if (generator == "ring") {
    const double r_in = card.real("r_in"), r_out = card.real("r_out");
    if (r_in >= r_out) card.fail("r_in", "must be smaller than r_out");
    verify_span(card, "r_out", 2 * std::numbers::sqrt2 * r_out);
    const int n = even_count(card, "N", 2);
    RingOptions options;
    if (card.has("layers")) options.layers = static_cast<int>(card.integer("layers"));
    verify_size(card, card.has("layers") ? "layers" : "N",
                static_cast<double>(n) *
                    (options.layers > 0 ? options.layers : default_ring_layers(n)));
    if (card.has("gamma1_above")) options.gamma1_above = card.real("gamma1_above");
    if (card.has("gamma3_below")) options.gamma3_below = card.real("gamma3_below");
    return ring(centre_within(card, r_out), r_in, r_out, n, options);
  }
  const CellPattern pattern = card.choice("pattern", {"alternating", "union-jack"}) == "union-jack"
                                  ? CellPattern::union_jack
                                  : CellPattern::alternating;
  const double lx = card.real("lx");
  const int nx = static_cast<int>(card.integer("nx"));
  const double ly = generator == "rectangle" ? card.real("ly") : lx;
  verify_span(card, lx >= ly || generator == "square" ? "lx" : "ly", std::hypot(lx, ly));
  const int ny = generator == "rectangle" ? static_cast<int>(card.integer("ny")) : nx;
  // Union-jack cells have a centre node each.
  verify_size(card, "nx",
              (nx + 1.0) * (ny + 1.0) + (pattern == CellPattern::union_jack ? 1.0 * nx * ny : 0.0));
  return rectangle(lx, ly, nx, ny, refs(card), pattern);
}

} // namespace

Mesh read_mesh_file(const std::filesystem::path& path) {
  const std::string extension = path.extension().string();
  if (extension == ".nopo") return read_nopo(path);
  SIG_VERIFY(extension == ".msh", path.string() << ": unknown mesh file extension '" << extension
                                                << "' (.nopo or .msh)");
  std::ifstream in(path);
  SIG_VERIFY(in, path.string() << ": cannot open the mesh file");
  std::string first;
  in >> first;
  return first == "$MeshFormat" ? read_gmsh(path) : read_freefem_msh(path);
}

Mesh mesh_from_card(const Card& card, const std::filesystem::path& folder) {
  if (card.has("file") == card.has("generator"))
    card.fail(card.has("file") ? "file" : "generator", "give either generator= or file=");
  std::string generator = card.has("file")
                              ? "file"
                              : card.choice("generator", {"half_disc", "half-disc", "disc", "ring",
                                                          "rectangle", "square", "box", "half_ball",
                                                          "half-ball", "ball", "cylinder"});
  std::replace(generator.begin(), generator.end(), '-', '_');
  const std::set<std::string>& allowed = fields_of(generator);
  for (const auto& [name, value] : card.fields) {
    if (name != "generator" && name != "file" && !allowed.count(name))
      card.fail(name,
                "is not used by " + (generator == "file" ? std::string("a mesh file") : generator));
  }
  if (generator == "file") return mesh_from_file(card, folder);
  try {
    return generate(card, generator);
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {
    // What the generated mesh breaks (a flat triangle of lx=4 ly=1e-20) comes from this card.
    card.fail("generator", e.what());
  }
}

std::vector<BoundaryArc> boundary_arcs(const Card& card) {
  if (!card.has("generator")) return {};
  std::string generator =
      card.choice("generator", {"half_disc", "half-disc", "disc", "ring", "rectangle", "square"});
  std::replace(generator.begin(), generator.end(), '-', '_');
  if (generator == "half_disc") {
    const double r = card.real("R");
    return {{3, {0, r}, r}};
  }
  if (generator == "disc") {
    const double r = card.real("R");
    const Eigen::Vector2d c = centre(card, 2);
    return {{1, c, r}, {2, c, r}, {3, c, r}, {4, c, r}};
  }
  if (generator == "ring") {
    const Eigen::Vector2d c = centre(card, 2);
    const double r_in = card.real("r_in"), r_out = card.real("r_out");
    return {{2, c, r_out}, {3, c, r_out}, {4, c, r_in}};
  }
  return {};
}

std::vector<int> card_regions(const Card& card, const Mesh& mesh) {
  const std::vector<int> present = mesh.subdomains();
  if (!card.has("region")) return present;
  std::vector<int> regions;
  for (long region : card.integers("region")) {
    if (!std::binary_search(present.begin(), present.end(), static_cast<int>(region))) {
      std::ostringstream what;
      what << "sub-domain " << region << " is not in the mesh; sub-domains present:";
      for (int n : present)
        what << " " << n;
      card.fail("region", what.str());
    }
    regions.push_back(static_cast<int>(region));
  }
  return regions;
}

} // namespace sig
