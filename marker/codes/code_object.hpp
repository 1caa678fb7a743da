#pragma once
// A code as a job holds it: what to encode and how to lay its modules out. Encoded and placed
// when the job is compiled, like a text object is laid out.
#include "marker/codes/code_marks.hpp"
#include "marker/codes/code_spec.hpp"

namespace mark {

struct CodeObject {
  CodeSpec spec;
  CodeLayout layout;
};

// Encodes (zint) and places the modules as marks. Throws InputError for data that cannot be
// encoded or a layout outside its ranges.
PlacedCode place_encoded(const CodeObject& code);

}  // namespace mark
