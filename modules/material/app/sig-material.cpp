// sig-material: the stage's executable, its work in sig::material_main
// (modules/material/src/material_main.cpp).
#include "material/stage_main.hpp"

int main(int argc, char** argv) {
  return sig::material_main(argc, argv);
}
