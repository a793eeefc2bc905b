#include "mesh/mesh_card.hpp"

#include "core/error.hpp"
#include "mesh/freefem.hpp"
#include "mesh/generators.hpp"
#include "mesh/gmsh.hpp"
#include "mesh/nopo.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace sig {
namespace {

/// Fields each generator reads; any other field on the card is an error.
const std::set<std::string>& fields_of(const std::string& generator) {
  static const std::map<std::string, std::set<std::string>> fields = {
      {"half_disc", {"r", "n", "grading"}},
      {"disc", {"center", "r", "n", "grading", "arcs"}},
      {"ring", {"center", "r_in", "r_out", "n", "layers", "gamma1_above", "gamma3_below"}},
      {"rectangle", {"lx", "ly", "nx", "ny", "refs", "pattern"}},
      {"square", {"lx", "nx", "refs", "pattern"}},
      {"file", {}},
  };
  return fields.at(generator);
}

double positive(const Card& card, const std::string& name) {
  const double value = card.real(name);
  if (!(value > 0) || !std::isfinite(value)) card.fail(name, "must be > 0");
  return value;
}

int count(const Card& card, const std::string& name, int minimum) {
  const long value = card.integer(name);
  if (value < minimum || value > 1 << 24)
    card.fail(name, "must be an integer >= " + std::to_string(minimum));
  return static_cast<int>(value);
}

int even_count(const Card& card, const std::string& name, int multiple) {
  const int value = count(card, name, 4);
  if (value % multiple != 0)
    card.fail(name, multiple == 2
                        ? std::string("must be even and >= 4")
                        : "must be a multiple of " + std::to_string(multiple) + " and >= 4");
  return value;
}

double grading(const Card& card) {
  const double value = card.real("grading");
  if (!(value >= 0) || !std::isfinite(value)) card.fail("grading", "must be >= 0");
  return value;
}

Eigen::Vector2d center(const Card& card) {
  const std::vector<double> c = card.reals("center");
  if (c.size() != 2) card.fail("center", "expects two coordinates, e.g. center=0,10");
  return {c[0], c[1]};
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
  if (!std::filesystem::is_regular_file(path) || !std::ifstream(path))
    card.fail("file", "cannot read " + path.string());
  return read_mesh_file(path);
}

Mesh generate(const Card& card, const std::string& generator) {
  if (generator == "half_disc")
    return half_disc(positive(card, "r"), even_count(card, "n", 2), grading(card));
  if (generator == "disc")
    return disc(center(card), positive(card, "r"), even_count(card, "n", 4), grading(card),
                card.choice("arcs", {"uniform", "graded"}, "uniform") == "graded");
  if (generator == "ring") {
    const double r_in = positive(card, "r_in"), r_out = positive(card, "r_out");
    if (r_in >= r_out) card.fail("r_in", "must be smaller than r_out");
    const int n = even_count(card, "n", 2);
    RingOptions options;
    if (card.has("layers")) options.layers = count(card, "layers", 2);
    if (card.has("gamma1_above")) options.gamma1_above = card.real("gamma1_above");
    if (card.has("gamma3_below")) options.gamma3_below = card.real("gamma3_below");
    return ring(center(card), r_in, r_out, n, options);
  }
  const CellPattern pattern = card.choice("pattern", {"alternating", "union-jack"}) == "union-jack"
                                  ? CellPattern::union_jack
                                  : CellPattern::alternating;
  if (generator == "rectangle")
    return rectangle(positive(card, "lx"), positive(card, "ly"), count(card, "nx", 1),
                     count(card, "ny", 1), refs(card), pattern);
  const double l = positive(card, "lx");
  const int n = count(card, "nx", 1);
  return rectangle(l, l, n, n, refs(card), pattern);
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
                                                          "rectangle", "square"});
  std::replace(generator.begin(), generator.end(), '-', '_');
  const std::set<std::string>& allowed = fields_of(generator);
  for (const auto& [name, value] : card.fields) {
    if (name != "generator" && name != "file" && !allowed.count(name))
      card.fail(name,
                "is not used by " + (generator == "file" ? std::string("a mesh file") : generator));
  }
  return generator == "file" ? mesh_from_file(card, folder) : generate(card, generator);
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
