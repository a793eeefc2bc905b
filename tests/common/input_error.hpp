#pragma once
// For the tests of what a bad input's error names (file, line, field): the error itself.
#include "core/error.hpp"

#include <gtest/gtest.h>

namespace sig::testing {

/// The InputError `body` throws; a test failure, and an empty error, when it throws none.
template <class F> InputError input_error(F&& body) {
  try {
    body();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError thrown";
  return InputError("", 0, "", "");
}

} // namespace sig::testing
