#pragma once
// A body built from a deck for the march tests: the mesh, its assembled system and its contact
// elements (none without a CONTACT card), as the stages build them; and the contact Newton they
// march with.
#include "assembly/system.hpp"
#include "contact/contact_elements.hpp"
#include "core/datafile.hpp"
#include "material/mili.hpp"
#include "mesh/mesh.hpp"
#include "solver/contact_method.hpp"

#include <optional>
#include <string>
#include <utility>

namespace sig::test {

struct DeckCase {
  Mesh mesh;
  LinearSystem system;
  std::optional<ContactElements> contact;
};

/// The cards of `deck` (read as the file `file`, the name its messages give) on `mesh`.
inline DeckCase deck_case(Mesh mesh, const std::string& deck, const std::string& file) {
  const Datafile datafile = Datafile::parse(deck, file);
  DeckCase c;
  c.system = assemble_system(mesh, material_table_from_cards(datafile, mesh), datafile);
  c.contact = contact_from_cards(datafile, mesh);
  c.mesh = std::move(mesh);
  return c;
}

/// PDAS to the tolerance eps within 50 iterations.
inline ContactSolverParameters pdas_newton(double eps) {
  ContactSolverParameters p;
  p.method = "pdas";
  p.eps = eps;
  p.max_iterations = 50;
  return p;
}

} // namespace sig::test
