#pragma once
// What a fuzz target does when an invariant breaks: say which on stderr and abort, so libFuzzer
// keeps the input as a crash.
#include <cstdio>
#include <cstdlib>

namespace mark::fuzz {

[[noreturn]] inline void broken(const char* what) {
  std::fprintf(stderr, "fuzz invariant broken: %s\n", what);
  std::abort();
}

}  // namespace mark::fuzz
