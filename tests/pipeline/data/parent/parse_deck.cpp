// Reads a datafile with Signorini::core built as a subdirectory and prints its cards.
#include "core/datafile.hpp"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  try {
    const sig::Datafile deck = sig::Datafile::read(argv[1]);
    for (const sig::Card& card : deck.cards())
      std::printf("%s\n", card.keyword.c_str());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "parse_deck: %s\n", e.what());
    return 1;
  }
}
