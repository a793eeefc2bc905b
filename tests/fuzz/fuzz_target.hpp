#pragma once
// The contract every reader is fuzzed against: any input is either read or refused with a
// sig::Error (which names the file); any other exception (std::bad_alloc from a trusted count,
// std::out_of_range ...), a crash, a sanitizer report, a hang or a huge allocation is a defect.
// Each fuzz_<reader>.cpp defines read_input(); this header gives it the libFuzzer entry point,
// which replay_main.cpp also drives over the committed corpus in every build (ctest).
#include "core/error.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

namespace sig::fuzz {
/// Read `bytes` as the reader under test would read a file; may throw sig::Error.
void read_input(const std::string& bytes);
} // namespace sig::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    sig::fuzz::read_input(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const sig::Error&) {
    // refused with a message: what a reader must do with a bad file
  }
  return 0;
}
