// sig-contact: the stage's executable, its work in sig::contact_main
// (modules/contact/src/contact_main.cpp).
#include "contact/stage_main.hpp"

int main(int argc, char** argv) {
  return sig::contact_main(argc, argv);
}
