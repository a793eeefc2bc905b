// sig-solve: the stage's executable, its work in sig::solve_main
// (modules/stages/src/solve_main.cpp).
#include "stages/stage_mains.hpp"

int main(int argc, char** argv) {
  return sig::solve_main(argc, argv);
}
