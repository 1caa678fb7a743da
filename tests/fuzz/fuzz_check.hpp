#pragma once
// What the LMC fuzz targets do when an invariant breaks: say which, and abort so libFuzzer keeps
// the input.
#include <cstdio>
#include <cstdlib>

namespace mark::fuzz {

[[noreturn]] inline void broken(const char* what) {
  std::fprintf(stderr, "fuzz invariant broken: %s\n", what);
  std::abort();
}

}  // namespace mark::fuzz
