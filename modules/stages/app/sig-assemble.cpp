// sig-assemble: the stage's executable, its work in sig::assemble_main
// (modules/stages/src/assemble_main.cpp).
#include "stages/stage_mains.hpp"

int main(int argc, char** argv) {
  return sig::assemble_main(argc, argv);
}
