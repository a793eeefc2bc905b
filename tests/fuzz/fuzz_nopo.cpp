// NOPO reader: FreeFem's 8-byte layout and MODULEF's classic 4-byte one, and our i8r8 case.nopo
// with its fingerprint (seeds of each in corpus/nopo).
#include "fuzz_target.hpp"
#include "mesh/nopo.hpp"

void sig::fuzz::read_input(const std::string& bytes) {
  parse_nopo_file("fuzz.nopo", bytes);
}
