// sig-march: the stage's executable, its work in sig::march_main
// (modules/stages/src/march_main.cpp).
#include "stages/stage_mains.hpp"

int main(int argc, char** argv) {
  return sig::march_main(argc, argv);
}
