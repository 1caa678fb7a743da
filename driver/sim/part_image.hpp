#pragma once
// A window of the part after marking: the dose raster spread by the beam's Gaussian profile into
// fluence, and marked where the fluence reaches the material's threshold (mark_response.hpp).
// Pixels sit on the dose raster's grid or a whole multiple of it, row 0 at the bottom (y up,
// like the field).
//
// A camera image is the part seen from above, row 0 at the top: light where the part is bare,
// dark where it is marked, each camera pixel the average of the part pixels it covers.
#include <cstdint>
#include <vector>

#include "driver/sim/dose_raster.hpp"
#include "driver/sim/mark_response.hpp"

namespace mark {

// A rectangle of the field, mm.
struct FieldWindow {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

class PartImage {
 public:
  // The fluence and threshold are worked out on the dose raster's own pixels (fine enough for
  // the beam), strip by strip where there is dose; each pixel of the image holds the marked
  // share of the `pixel_factor` × `pixel_factor` raster pixels it covers. Throws
  // std::invalid_argument for an empty window, a factor below 1, or more than max_pixels pixels.
  static PartImage render(const DoseRaster& dose, const FieldWindow& window,
                          const MarkResponse& response, int pixel_factor = 1,
                          std::int64_t max_pixels = 64'000'000);

  int width() const { return width_; }
  int height() const { return height_; }
  double pixel_mm() const { return pixel_mm_; }
  // Centre of pixel (0, 0) in the field, mm.
  double x0_mm() const { return x0_; }
  double y0_mm() const { return y0_; }
  // Marked share of the pixel's area, 0..1.
  float share(int i, int j) const { return share_[index(i, j)]; }
  bool marked(int i, int j) const { return share_[index(i, j)] >= 0.5f; }
  // The marked share at a field point (its pixel's), 0 outside the window.
  float share_at(double x_mm, double y_mm) const;

 private:
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * width_ + i; }
  int width_ = 0, height_ = 0;
  double pixel_mm_ = 0, x0_ = 0, y0_ = 0;
  std::vector<float> share_;
};

struct CameraImage {
  int width = 0;
  int height = 0;
  double pixel_mm = 0;
  std::vector<std::uint8_t> grey;  // row 0 at the top
  std::uint8_t at(int x, int y) const { return grey[static_cast<std::size_t>(y) * width + x]; }
};

// Grey levels of the bare and the marked part as the camera sees them (annealed steel under
// diffuse light: a mark reflects about a sixth of the bare surface).
inline constexpr std::uint8_t kBareGrey = 225, kMarkedGrey = 40;

// The part seen with camera pixels of `factor` part pixels square; `invert` swaps bare and
// marked grey (a dark part whose marks turn light, e.g. black anodised aluminium).
CameraImage camera_view(const PartImage& part, int factor, bool invert = false);

// The window's part as a camera sees it, at the raster's pixel or the smallest whole multiple
// of it that keeps both sides within max_side_px.
CameraImage part_picture(const DoseRaster& dose, const FieldWindow& window, const MarkResponse& response,
                         bool dark_part = false, int max_side_px = 4096);

// Everything the beam dosed (whole raster tiles), grown by margin_mm; false when nothing was.
bool dosed_window(const DoseRaster& dose, double margin_mm, FieldWindow& window);

}  // namespace mark
