// sig-estimate: the stage's executable, its work in sig::estimate_main
// (modules/post/src/estimate_main.cpp).
#include "post/stage_mains.hpp"

int main(int argc, char** argv) {
  return sig::estimate_main(argc, argv);
}
