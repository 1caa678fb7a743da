#pragma once
// printf-style formatting: format() into a string, print() onto std::cout — one stream for
// everything a command prints, so its text and its JSON never interleave out of order. Lines
// longer than 512 bytes are cut.
#include <cstdio>
#include <iostream>
#include <string>

namespace mark::cli {

template <class... T>
std::string format(const char* pattern, T... values) {
  char line[512];
  std::snprintf(line, sizeof line, pattern, values...);
  return line;
}

template <class... T>
void print(const char* pattern, T... values) {
  std::cout << format(pattern, values...);
}

}  // namespace mark::cli
