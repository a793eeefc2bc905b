// sig-post: the stage's executable, its work in sig::post_main
// (modules/post/src/post_main.cpp).
#include "post/stage_mains.hpp"

int main(int argc, char** argv) {
  return sig::post_main(argc, argv);
}
