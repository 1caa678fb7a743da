#include "fonts/loaders/text_lines.hpp"

#include <cstdio>

#include "fonts/error.hpp"
#include "fonts/utf8.hpp"

namespace mark::loaders {
namespace {

// The line starting at `pos` and where the one after it starts.
std::string_view line_at(std::string_view text, std::size_t pos, std::size_t& next_pos) {
  std::size_t end = text.find('\n', pos);
  if (end == std::string_view::npos) {
    end = text.size();
    next_pos = end;
  } else {
    next_pos = end + 1;
  }
  std::string_view line = text.substr(pos, end - pos);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

}  // namespace

bool LineReader::next(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  line = line_at(text_, pos_, pos_);
  ++line_;
  return true;
}

bool LineReader::peek(std::string_view& line) const {
  if (pos_ >= text_.size()) return false;
  std::size_t ignored;
  line = line_at(text_, pos_, ignored);
  return true;
}

void check_text_line(std::string_view line, TextEncoding encoding, const std::string& source,
                     std::size_t line_number) {
  // One branch-free pass (the compiler vectorises it); the culprit is located only on failure.
  unsigned char control = 0, high = 0;
  const auto* bytes = reinterpret_cast<const unsigned char*>(line.data());
  for (std::size_t i = 0; i < line.size(); ++i) {
    const unsigned char b = bytes[i];
    control |= static_cast<unsigned char>((b < 0x20) & (b != '\t'));
    high |= b;
  }
  if (control) {
    for (std::size_t i = 0; i < line.size(); ++i) {
      const auto b = static_cast<unsigned char>(line[i]);
      if (b < 0x20 && b != '\t') {
        char msg[64];
        std::snprintf(msg, sizeof msg, "binary data: control byte 0x%02X at column %zu", b, i + 1);
        throw FontFileError(source, line_number, msg);
      }
    }
  }
  high &= 0x80;
  if (high && encoding == TextEncoding::utf8) {
    try {
      decode_utf8(line, "text");
    } catch (const InputError& e) {
      throw FontFileError(source, line_number, e.what());  // "text: invalid UTF-8 at byte N"
    }
  }
}

std::string quote(std::string_view text) {
  // Messages are one printable line: control bytes, and every byte of text that is not valid
  // UTF-8 (a binary file), are written as \xNN.
  bool utf8 = true;
  try {
    decode_utf8(text, "text");
  } catch (const InputError&) {
    utf8 = false;
  }
  std::string s = "'";
  std::size_t shown = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto b = static_cast<unsigned char>(text[i]);
    // Shorten to about 40 bytes, not inside a UTF-8 sequence.
    if (shown >= 37 && (b & 0xC0) != 0x80 && text.size() > 40) {
      s += "...";
      break;
    }
    if (b < 0x20 || b == 0x7F || (b >= 0x80 && !utf8)) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", b);
      s += hex;
    } else {
      s += static_cast<char>(b);
    }
    ++shown;
  }
  return s + "'";
}

}  // namespace mark::loaders
