#pragma once
// Errors that name the input and the place. Library code throws these; the CLI prints what()
// as one line and exits non-zero.
#include <stdexcept>
#include <string>

namespace mark {

// Bad input of any kind: a malformed font file, an unknown glyph, an impossible parameter.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

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
