#pragma once
// Test support: the one-line message of the InputError that `f` throws, or "" when it throws
// none (any other exception fails the test by escaping).
#include <functional>
#include <string>

#include "fonts/error.hpp"

namespace mark::test {

inline std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace mark::test
