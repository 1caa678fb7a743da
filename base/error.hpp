#pragma once
// The one exception type for bad input, below every stage: fonts, the simulator, the engine and
// the command line all throw it, so none of them depends on another for an error type. The
// message names the input, the place and the allowed range; the command line prints what() as
// one line and exits 1.
#include <stdexcept>

namespace mark {

// Bad input of any kind: a malformed file, an unknown glyph, an impossible parameter.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace mark
