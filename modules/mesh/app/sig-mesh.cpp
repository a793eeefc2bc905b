// sig-mesh: the stage's executable, its work in sig::mesh_main
// (modules/mesh/src/mesh_main.cpp).
#include "mesh/stage_main.hpp"

int main(int argc, char** argv) {
  return sig::mesh_main(argc, argv);
}
