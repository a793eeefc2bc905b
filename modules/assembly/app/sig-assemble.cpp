// sig-assemble: the stage's executable, its work in sig::assemble_main
// (modules/assembly/src/assemble_main.cpp).
#include "assembly/stage_main.hpp"

int main(int argc, char** argv) {
  return sig::assemble_main(argc, argv);
}
