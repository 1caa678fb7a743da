#include "marker/gravure/cell_source.hpp"

#include <algorithm>

namespace mark {

std::size_t CellList::next(std::span<CellValues> out) {
  const std::size_t n = std::min(out.size(), cells_.size() - at_);
  std::copy_n(cells_.begin() + static_cast<std::ptrdiff_t>(at_), n, out.begin());
  at_ += n;
  return n;
}

}  // namespace mark
