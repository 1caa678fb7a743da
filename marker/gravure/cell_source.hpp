#pragma once
// Where the cells come from, in engraving order (track after track, each along the track): an
// image through a screen (image_cells.hpp) or a list (tests, test patterns).
#include <cstdint>
#include <span>
#include <vector>

#include "marker/gravure/control_points.hpp"

namespace mark {

class CellSource {
 public:
  virtual ~CellSource() = default;
  // Cells in the whole job.
  virtual std::uint64_t cells() const = 0;
  // The next cells, up to out.size(); 0 at the end.
  virtual std::size_t next(std::span<CellValues> out) = 0;
  // Back to the first cell (the same job is run filtered and unfiltered).
  virtual void rewind() = 0;
};

class CellList : public CellSource {
 public:
  explicit CellList(std::vector<CellValues> cells) : cells_(std::move(cells)) {}
  std::uint64_t cells() const override { return cells_.size(); }
  std::size_t next(std::span<CellValues> out) override;
  void rewind() override { at_ = 0; }

 private:
  std::vector<CellValues> cells_;
  std::size_t at_ = 0;
};

}  // namespace mark
