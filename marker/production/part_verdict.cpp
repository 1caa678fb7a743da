#include "marker/production/part_verdict.hpp"

namespace mark {

std::optional<Rejection> part_verdict(const std::vector<MarkedObject>& objects) {
  for (std::size_t i = 0; i < objects.size(); ++i)
    if (auto why = requirement_shortfall(*objects[i].spec, *objects[i].marked, objects[i].require))
      return Rejection{i, std::move(*why)};
  return std::nullopt;
}

}  // namespace mark
