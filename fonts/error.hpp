#pragma once
// Font errors that name the input and the place (InputError itself is base/error.hpp).
#include <string>

#include "base/error.hpp"

namespace mark {

// A malformed font file: the message names the file, the line and what is wrong.
class FontFileError : public InputError {
 public:
  FontFileError(const std::string& source, std::size_t line, const std::string& what)
      : InputError(source + ":" + std::to_string(line) + ": " + what) {}
};

// A text asks for a character the font does not have.
class MissingGlyphError : public InputError {
 public:
  using InputError::InputError;
};

}  // namespace mark
