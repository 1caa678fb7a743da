#include "marker/codes/code_data.hpp"

#include <cstdio>

#include "base/error.hpp"

namespace mark {
namespace {

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

std::string unescape_code_data(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\\') {
      out += text[i];
      continue;
    }
    const auto fail = [&](const std::string& what) -> void {
      throw InputError("code data, character " + std::to_string(i + 1) + ": " + what +
                       " (escapes: \\\\ \\n \\r \\t \\0 \\G \\R \\E \\xHH)");
    };
    if (i + 1 >= text.size()) fail("a backslash ends the data");
    const char c = text[++i];
    switch (c) {
      case '\\': out += '\\'; break;
      case 'n': out += '\n'; break;
      case 'r': out += '\r'; break;
      case 't': out += '\t'; break;
      case '0': out += '\0'; break;
      case 'G': out += '\x1d'; break;
      case 'R': out += '\x1e'; break;
      case 'E': out += '\x04'; break;
      case 'x': {
        const int hi = i + 1 < text.size() ? hex_value(text[i + 1]) : -1;
        const int lo = i + 2 < text.size() ? hex_value(text[i + 2]) : -1;
        if (hi < 0 || lo < 0) fail("\\x needs two hex digits");
        out += static_cast<char>(hi * 16 + lo);
        i += 2;
        break;
      }
      default: fail(std::string("unknown escape \\") + c);
    }
  }
  return out;
}

std::string printable_bytes(std::string_view bytes) {
  std::string out;
  for (const char ch : bytes) {
    const auto c = static_cast<unsigned char>(ch);
    if (c >= 0x20 && c != 0x7f && c != '\\') {  // UTF-8 sequences pass
      out += static_cast<char>(c);
    } else if (c == '\\') {
      out += "\\\\";
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", c);
      out += buf;
    }
  }
  return out;
}

}  // namespace mark
