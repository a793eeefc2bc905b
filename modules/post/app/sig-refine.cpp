// sig-refine: the stage's executable, its work in sig::refine_main
// (modules/post/src/refine_main.cpp).
#include "post/stage_mains.hpp"

int main(int argc, char** argv) {
  return sig::refine_main(argc, argv);
}
