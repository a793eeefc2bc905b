#pragma once
// What a file of a case records of the deck it was made from (core/provenance.hpp): for each card
// keyword its stage reads (core/stage_cards.hpp), the parsed values of the deck's cards of that
// keyword as a canonical text, and the fingerprint of that text. Values, not text:
//  - a number is the shortest text that reads back to the same double (1e3, 1000 and +1000.0
//    are all "1000"; -0 is "0"), a list item by item, a choice in lower case (the stages read
//    choices case-insensitively), a mesh file (MESH file=) the fingerprint of its contents (the
//    mesh rewritten in place is another mesh; the same mesh under another path is not);
//  - the fields in the schema's order, an absent field by the schema's default (a default
//    spelled out changes nothing), an absent field without one left out;
//  - comments, blank lines, spacing, the case of keywords and field names, the order of the
//    fields and the place of a card in the deck change nothing. Several cards of one keyword are
//    a set (MATERIAL per region, the loads), except where a later card overrides an earlier one
//    (DIRICHLET, INITIAL): those keep their order.
// An absent card is recorded too ("(absent)"): adding one is a change. A default the stages
// choose in code rather than in the schema (SOLVER maxit: 100 in sig-solve, 50 in sig-march) is
// not known here: spelling it out counts as a change, which reruns a stage for nothing but never
// keeps a stale file.
#include <cstdint>
#include <string>

namespace sig {

class Datafile;

/// The cards of one keyword of a deck, as a file records them.
struct CardRecord {
  std::string keyword;           ///< upper case: FRICTION
  std::uint64_t fingerprint = 0; ///< of `values` (fnv1a64)
  /// "law=coulomb mu=0.4 bound=normal of=slip"; cards of a repeatable keyword are joined by
  /// " | "; "(absent)" without one.
  std::string values;
};

/// The record of the cards `keyword` of `deck` (keyword case-insensitive).
CardRecord card_record(const Datafile& deck, const std::string& keyword);

/// What changed between a record and the deck, in the user's words, the fields that differ
/// only: "with FRICTION mu=0.4, but c.dat:12 now says FRICTION mu=0.05". Empty when the deck
/// still gives the recorded values.
std::string card_change(const CardRecord& recorded, const Datafile& deck);

} // namespace sig
