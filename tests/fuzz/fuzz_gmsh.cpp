// gmsh .msh reader, formats 2.2 and 4.1, ASCII and binary (seeds of each in corpus/gmsh).
#include "fuzz_target.hpp"
#include "mesh/gmsh.hpp"

void sig::fuzz::read_input(const std::string& bytes) {
  parse_gmsh("fuzz.msh", bytes);
}
