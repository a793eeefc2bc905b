#include "assembly/cards.hpp"

#include "core/datafile.hpp"
#include "mesh/mesh.hpp"

#include <algorithm>
#include <sstream>

namespace sig {

namespace {

std::vector<int> edge_references(const Mesh& mesh) {
  std::vector<int> refs;
  for (const Facet& e : mesh.facets)
    refs.push_back(e.ref);
  std::sort(refs.begin(), refs.end());
  refs.erase(std::unique(refs.begin(), refs.end()), refs.end());
  return refs;
}

void list(std::ostringstream& out, const std::vector<int>& numbers) {
  if (numbers.empty()) out << " none";
  for (int n : numbers)
    out << " " << n;
}

} // namespace

std::vector<int> card_references(const Card& card, const Mesh& mesh, RefSupport support) {
  const std::vector<int> present =
      support == RefSupport::edges ? edge_references(mesh) : mesh.references();
  std::vector<int> refs;
  for (long ref : card.integers("ref")) {
    if (!std::binary_search(present.begin(), present.end(), static_cast<int>(ref))) {
      std::ostringstream what;
      what << "reference " << ref << " is on no " << mesh.facet_name()
           << (support == RefSupport::edges ? "" : " or vertex")
           << " of the mesh; references present:";
      list(what, present);
      card.fail("ref", what.str());
    }
    refs.push_back(static_cast<int>(ref));
  }
  return refs;
}

} // namespace sig
