#pragma once
// Whether a part marked to its end is good: each object's mark judged against what the object
// requires (marker/job/mark_requirement.hpp): every code it carries read back off the mark to
// exactly its data, and the quality class and code grade its "require" asks. A part short of it
// is scrap, whatever the device said; it is rejected, naming the object and why. Only what the
// evaluator read back is judged: on a device without one (an LMC board, no camera) there is
// nothing to judge and the part stands as marked.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "marker/job/mark_requirement.hpp"

namespace mark {

struct Rejection {
  std::size_t object = 0;  // index of the first object that failed
  std::string reason;      // "code 1 not decoded (modules wrong: 113)"
};

// One object of a marked part: its job (with the part's text), what the device and evaluator
// gave back, and what the object requires. Not owned.
struct MarkedObject {
  const JobSpec* spec = nullptr;
  const JobResult* marked = nullptr;
  MarkRequirement require;
};

// The first object, in object order, that falls short; nothing when every object meets its own.
std::optional<Rejection> part_verdict(const std::vector<MarkedObject>& objects);

}  // namespace mark
