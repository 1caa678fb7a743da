#pragma once
// printf-style formatting onto std::cout — one stream for everything a command prints, so its
// text and its JSON never interleave out of order. Lines longer than 512 bytes are cut.
#include <cstdio>
#include <iostream>

namespace mark::cli {

template <class... T>
void print(const char* format, T... values) {
  char line[512];
  std::snprintf(line, sizeof line, format, values...);
  std::cout << line;
}

}  // namespace mark::cli
