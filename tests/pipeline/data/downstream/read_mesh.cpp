// Reads a mesh file (NOPO, gmsh or FreeFem) with the installed Signorini::mesh and prints its
// counts: what a downstream user of the library does first.
#include "mesh/mesh.hpp"
#include "mesh/mesh_card.hpp"

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: read_mesh FILE\n");
    return 2;
  }
  try {
    const sig::Mesh mesh = sig::read_mesh_file(argv[1]);
    std::printf("nodes %d triangles %d\n", mesh.num_nodes(), mesh.num_cells());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "read_mesh: %s\n", e.what());
    return 1;
  }
}
