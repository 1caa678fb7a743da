#pragma once
// Whether a part marked to its end is good: every code it carries must be read back off the
// mark and decode to exactly its data (the deciding readers of marker/codes/verify.hpp). A code
// that does not read is scrap, whatever the device said; the part is rejected, naming the object
// and the code. Only what the evaluator read back is judged: on a device without one (an LMC
// board, no camera) there is nothing to judge and the part stands as marked.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "marker/codes/verify.hpp"

namespace mark {

struct Rejection {
  std::size_t object = 0;  // index of the first object that failed
  std::string reason;      // "code 1 not decoded (modules wrong: 113)"
};

// The codes read back of each object, in object order (empty: none read back).
std::optional<Rejection> part_verdict(const std::vector<std::vector<CodeVerification>>& codes_per_object);

}  // namespace mark
