#pragma once
// Where a load or boundary card applies: the references (ref=) and sub-domains (region=) it
// names, checked against the mesh so that a typo in a deck is an error on its line, not a load
// silently applied nowhere.
#include "mesh/mesh_card.hpp" // card_regions, shared with the material cards

#include <vector>

namespace sig {

class Card;
struct Mesh;

enum class RefSupport { edges, edges_or_vertices };

/// The references of the card's field `ref` (one number or a list). Throws sig::InputError on the
/// card line and field 'ref' for a reference that no edge (or vertex, if allowed) carries:
/// "reference 7 is on no edge or vertex of the mesh; references present: 1 2 3".
std::vector<int> card_references(const Card& card, const Mesh& mesh, RefSupport support);

} // namespace sig
