#include "core/stage_cards.hpp"

#include "core/error.hpp"

#include <algorithm>

namespace sig {

const std::vector<StageCards>& stage_table() {
  static const std::vector<StageCards> table = {
      {"mesh", {"TITLE", "MESH"}, "nopo", "NOPO"},
      {"material", {"TITLE", "MATERIAL", "MEMORY"}, "mili", "MILI"},
      {"contact", {"TITLE", "CONTACT", "FRICTION"}, "cont", "CONT"},
      {"assemble",
       {"TITLE", "DIRICHLET", "TRACTION", "PRESSURE", "BODYFORCE", "MOVINGLOAD"},
       "tae",
       "TAE"},
      {"solve",
       {"TITLE", "SOLVER", "LOADSTEPS", "CONVEXIFICATION", "CONTACT", "FRICTION", "INITIAL",
        "TRACTION", "PRESSURE", "BODYFORCE", "DIRICHLET"},
       "b",
       "B"},
      {"march",
       {"TITLE", "TIME", "INITIAL", "CONTACT", "FRICTION", "SOLVER", "CONVEXIFICATION", "LOADSTEPS",
        "MATERIAL", "MEMORY"},
       "hist",
       "HIST"},
      {"post", {"TITLE", "OUTPUT", "TIME", "CONTACT", "COMPARE"}, "post", "POST"},
      // After the chain, as sig-error: drivers/adapt.sh runs it on a solved static case.
      {"estimate", {"TITLE", "OUTPUT", "TIME"}, "est", "EST"},
      // Writes a mesh file for the loop's next deck (MESH file=), recorded by its contents.
      {"refine", {"TITLE", "MESH"}, "", ""},
      {"bench-finite-strain",
       {"TITLE", "SOLVER", "LOADSTEPS", "CONVEXIFICATION", "CONTACT", "FRICTION"},
       "",
       ""},
      {"bench-quasistatic",
       {"TITLE", "TIME", "INITIAL", "CONTACT", "FRICTION", "SOLVER", "CONVEXIFICATION", "LOADSTEPS",
        "MATERIAL"},
       "",
       ""},
  };
  return table;
}

const StageCards& stage_cards(const std::string& name) {
  const std::string bare = name.rfind("sig-", 0) == 0 ? name.substr(4) : name;
  for (const StageCards& stage : stage_table())
    if (stage.name == bare) return stage;
  throw Error("no stage called '" + name + "' in the table of stages (core/stage_cards.cpp)");
}

std::vector<std::string> dependency_cards(const StageCards& stage) {
  std::vector<std::string> cards = stage.cards;
  // The title is in the headers of the DS files, which no stage reads back; sig-post's files
  // (summary.json, the .vtu) show it to the user.
  if (stage.name != "post") std::erase(cards, std::string("TITLE"));
  return cards;
}

const StageCards* stage_writing(const std::string& kind) {
  const auto& table = stage_table();
  const auto found = std::find_if(table.begin(), table.end(), [&](const StageCards& stage) {
    return !stage.kind.empty() && stage.kind == kind;
  });
  return found == table.end() ? nullptr : &*found;
}

} // namespace sig
