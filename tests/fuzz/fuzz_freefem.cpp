// FreeFem++ .msh reader.
#include "fuzz_target.hpp"
#include "mesh/freefem.hpp"

void sig::fuzz::read_input(const std::string& bytes) {
  parse_freefem_msh("fuzz.msh", bytes);
}
