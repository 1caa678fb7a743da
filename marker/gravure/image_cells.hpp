#pragma once
// Cells from an image: the artwork (grey levels; density = 1 − intensity, so white is 0 % and
// black 100 %) is laid on the cylinder at `px_per_mm`, its rows running along the tracks, and
// cut into the screen's cells. A cell's four density values are the mean density over the
// quarters of the cell along the track, across the full track pitch — exact area averages, each
// pixel weighted by how much of it lies in the quarter, so any image resolution works (finer
// than the screen: averaged; coarser: each quarter takes the pixels it overlaps). Where a
// quarter runs past the image edge (a staggered track's last cell) the outside counts as white.
//
// The optional line-work mask has the image's size; a quarter is line-work when the mask is at
// least half dark over it, and a cell takes the LW setup values when any of its quarters is
// line-work (a cell on the edge of type must cut as type).
#include <cstdint>
#include <optional>
#include <vector>

#include "marker/gravure/cell_source.hpp"
#include "marker/gravure/screen.hpp"
#include "marker/image/gray_image.hpp"

namespace mark {

class ImageCells : public CellSource {
 public:
  // Throws InputError if the mask's size differs from the image's or the resolution or screen
  // is out of range.
  ImageCells(const GrayImage& image, const GrayImage* mask, const GravureScreen& screen, double px_per_mm);

  std::uint64_t cells() const override { return static_cast<std::uint64_t>(tracks_) * cells_per_track_; }
  std::size_t next(std::span<CellValues> out) override;
  void rewind() override;

  std::uint32_t tracks() const { return tracks_; }
  std::uint32_t cells_per_track() const { return cells_per_track_; }
  double width_mm() const { return width_mm_; }
  double height_mm() const { return height_mm_; }

 private:
  void load_track(std::uint32_t track);
  // Cumulative band density up to pixel column position px (fractional), per image.
  static double cumulative(const std::vector<double>& prefix, double px);

  const GrayImage& image_;
  const GrayImage* mask_;
  GravureScreen screen_;
  double px_per_mm_;
  double width_mm_, height_mm_;
  std::uint32_t tracks_, cells_per_track_;
  std::vector<CellValues> track_;  // the current track's cells
  std::vector<double> prefix_, mask_prefix_;
  std::uint32_t track_index_ = 0;
  std::size_t in_track_ = 0;
  bool loaded_ = false;
};

}  // namespace mark
