// Datafile reader: parse, then read every field of every card the ways a stage reads them.
#include "core/datafile.hpp"
#include "fuzz_target.hpp"

void sig::fuzz::read_input(const std::string& bytes) {
  const Datafile deck = Datafile::parse(bytes, "fuzz.dat");
  deck.title();
  for (const Card& card : deck.cards()) {
    for (const auto& [name, value] : card.fields) {
      for (int way = 0; way < 5; ++way) {
        try {
          switch (way) {
          case 0:
            card.real(name);
            break;
          case 1:
            card.integer(name);
            break;
          case 2:
            card.reals(name);
            break;
          case 3:
            card.integers(name);
            break;
          default:
            card.file_name(name, "x");
          }
        } catch (const InputError&) {
          // a value of another kind, refused with the field: keep reading the others
        }
      }
    }
  }
}
