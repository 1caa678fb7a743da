#include "marker/codes/code_object.hpp"

namespace mark {

PlacedCode place_encoded(const CodeObject& code) {
  PlacedCode placed = place_code(encode_code(code.spec), code.layout);
  placed.spec = code.spec;
  return placed;
}

}  // namespace mark
