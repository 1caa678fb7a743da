#include "marker/codes/code_object.hpp"

namespace mark {

PlacedCode place_encoded(const CodeObject& code) { return place_code(encode_code(code.spec), code.layout); }

}  // namespace mark
