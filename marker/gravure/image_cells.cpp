#include "marker/gravure/image_cells.hpp"

#include <algorithm>
#include <cmath>

#include "base/error.hpp"
#include "marker/limits/gravure_settings.hpp"

namespace mark {
namespace {

// Column sums of density over the band of rows [y0, y1) (fractional, clipped to the image),
// each row weighted by its overlap, as a running prefix along the row: prefix[x] is the band's
// total density in columns [0, x), divided by the band height.
void band_prefix(const GrayImage& img, double y0, double y1, std::vector<double>& prefix) {
  prefix.assign(static_cast<std::size_t>(img.width) + 1, 0.0);
  const double height = y1 - y0;
  const int r0 = std::max(0, static_cast<int>(std::floor(y0)));
  const int r1 = std::min(img.height, static_cast<int>(std::ceil(y1)));
  std::vector<double> column(static_cast<std::size_t>(img.width), 0.0);
  for (int r = r0; r < r1; ++r) {
    const double w = std::min<double>(r + 1, y1) - std::max<double>(r, y0);
    if (w <= 0) continue;
    const float* row = img.pixels.data() + static_cast<std::size_t>(r) * img.width;
    for (int x = 0; x < img.width; ++x) column[x] += w * (1.0 - std::clamp(row[x], 0.0f, 1.0f));
  }
  for (int x = 0; x < img.width; ++x) prefix[x + 1] = prefix[x] + column[x] / height;
}

}  // namespace

ImageCells::ImageCells(const GrayImage& image, const GrayImage* mask, const GravureScreen& screen, double px_per_mm)
    : image_(image), mask_(mask), screen_(screen), px_per_mm_(px_per_mm) {
  validate(screen_);
  check_range("image resolution", px_per_mm_, kResolutionBounds.range());
  if (image.width < 1 || image.height < 1) throw InputError("gravure image: empty image");
  if (mask_ && (mask_->width != image.width || mask_->height != image.height))
    throw InputError("line-work mask is " + std::to_string(mask_->width) + "x" + std::to_string(mask_->height) +
                     " pixels, the image " + std::to_string(image.width) + "x" + std::to_string(image.height) +
                     ": they must be the same size");
  width_mm_ = image.width / px_per_mm_;
  height_mm_ = image.height / px_per_mm_;
  const double along = std::round(width_mm_ * screen_.cells_per_mm_along);
  const double across = std::round(height_mm_ * screen_.cells_per_mm_across);
  constexpr double kMaxCells = 1e9;
  if (along * across > kMaxCells)
    throw InputError("gravure image: " + std::to_string(along * across) + " cells is more than " +
                     std::to_string(kMaxCells));
  cells_per_track_ = static_cast<std::uint32_t>(std::max(1.0, along));
  tracks_ = static_cast<std::uint32_t>(std::max(1.0, across));
  track_.resize(cells_per_track_);
}

double ImageCells::cumulative(const std::vector<double>& prefix, double px) {
  const double width = static_cast<double>(prefix.size() - 1);
  if (px <= 0) return 0;
  if (px >= width) return prefix.back();
  const auto i = static_cast<std::size_t>(px);
  return prefix[i] + (px - i) * (prefix[i + 1] - prefix[i]);  // exact: pixels are constant
}

void ImageCells::load_track(std::uint32_t t) {
  const double track_px = px_per_mm_ / screen_.cells_per_mm_across;
  band_prefix(image_, t * track_px, (t + 1) * track_px, prefix_);
  if (mask_) band_prefix(*mask_, t * track_px, (t + 1) * track_px, mask_prefix_);
  const double quarter_px = px_per_mm_ / screen_.cells_per_mm_along / 4;
  const double shift = screen_.stagger && t % 2 == 1 ? 2 : 0;  // half a cell, in quarters
  for (std::uint32_t j = 0; j < cells_per_track_; ++j) {
    CellValues& c = track_[j];
    c.line_work = false;
    for (int q = 0; q < 4; ++q) {
      const double a = (4.0 * j + q + shift) * quarter_px, b = a + quarter_px;
      const double d = (cumulative(prefix_, b) - cumulative(prefix_, a)) / quarter_px;
      c.density[q] = static_cast<float>(std::clamp(d, 0.0, 1.0));
      if (mask_ && (cumulative(mask_prefix_, b) - cumulative(mask_prefix_, a)) / quarter_px >= 0.5)
        c.line_work = true;
    }
  }
}

std::size_t ImageCells::next(std::span<CellValues> out) {
  std::size_t n = 0;
  while (n < out.size() && track_index_ < tracks_) {
    if (!loaded_) {
      load_track(track_index_);
      loaded_ = true;
      in_track_ = 0;
    }
    const std::size_t take = std::min(out.size() - n, track_.size() - in_track_);
    std::copy_n(track_.begin() + static_cast<std::ptrdiff_t>(in_track_), take, out.begin() + static_cast<std::ptrdiff_t>(n));
    n += take;
    in_track_ += take;
    if (in_track_ == track_.size()) {
      ++track_index_;
      loaded_ = false;
    }
  }
  return n;
}

void ImageCells::rewind() {
  track_index_ = 0;
  in_track_ = 0;
  loaded_ = false;
}

}  // namespace mark
