#pragma once
// A window of the part after marking: the dose raster spread by the beam's Gaussian profile into
// fluence, marked where the fluence reaches the material's threshold (mark_response.hpp), and
// how much light each spot of it reflects (PartLook). Pixels sit on the dose raster's grid or a
// whole multiple of it, row 0 at the bottom (y up, like the field).
//
// The look is worked out on the raster's own 5 µm pixels, where the beam is resolved: a mark
// darkens with its fluence — half dark at the threshold (so the reference line is as wide as a
// camera sees it), fully dark `tone_ratio` times above it, untouched `tone_ratio` times below —
// so the stripes between hatch lines and the scallops between pulses show as they are; a
// machined surface's grain varies the reflectance pixel by pixel (seeded, and tied to the
// field position, so the same part looks the same in every window).
#include <cstdint>
#include <vector>

#include "base/grey_image.hpp"
#include "driver/sim/dose_raster.hpp"
#include "driver/sim/mark_response.hpp"

namespace mark {

// A rectangle of the field, mm.
struct FieldWindow {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
};

// How the surface reflects light, bare and marked (fractions of the light falling on it).
struct PartLook {
  double bare_reflectance = 0.55;  // bead-blasted stainless steel under diffuse light
  double mark_reflectance = 0.10;  // a fully darkened (annealed) mark
  double tone_ratio = 4;           // fluence ratio from half to full darkness (and from none to half)
  double grain_pct = 4;            // rms reflectance variation of the bare surface, per 5 µm spot
  std::uint32_t seed = 1;          // of the grain
};

class PartImage {
 public:
  // The fluence and threshold are worked out on the dose raster's own pixels (fine enough for
  // the beam), strip by strip where there is dose; each pixel of the image holds the marked
  // share and the mean reflectance of the `pixel_factor` × `pixel_factor` raster pixels it
  // covers. Throws std::invalid_argument for an empty window, a factor below 1, a look outside
  // its ranges, or more than max_pixels pixels.
  static PartImage render(const DoseRaster& dose, const FieldWindow& window,
                          const MarkResponse& response, int pixel_factor = 1,
                          const PartLook& look = {}, std::int64_t max_pixels = 64'000'000);

  int width() const { return width_; }
  int height() const { return height_; }
  double pixel_mm() const { return pixel_mm_; }
  // Centre of pixel (0, 0) in the field, mm.
  double x0_mm() const { return x0_; }
  double y0_mm() const { return y0_; }
  // Marked share of the pixel's area, 0..1.
  float share(int i, int j) const { return share_[index(i, j)]; }
  bool marked(int i, int j) const { return share_[index(i, j)] >= 0.5f; }
  // Mean reflectance of the pixel's area.
  float reflectance(int i, int j) const { return reflectance_[index(i, j)]; }
  // The marked share at a field point (its pixel's), 0 outside the window.
  float share_at(double x_mm, double y_mm) const;
  // The same part at k × k times coarser pixels (each the mean of the pixels it covers; a last
  // partial row or column of the window averages what it has).
  PartImage binned(int k) const;

 private:
  std::size_t index(int i, int j) const { return static_cast<std::size_t>(j) * width_ + i; }
  int width_ = 0, height_ = 0;
  double pixel_mm_ = 0, x0_ = 0, y0_ = 0;
  std::vector<float> share_, reflectance_;
};

// Throws std::invalid_argument naming the value outside its range (reflectances 0.001 .. 1,
// tone ratio 1.01 .. 1000, grain 0 .. 50 %).
void check_part_look(const PartLook& look);

// The look of a dark part whose marks turn light (black anodised aluminium): bare and mark
// reflectance swapped.
PartLook dark_part_look(PartLook look);

// The part as it is, seen from above (row 0 at the top): grey = reflectance × 255 / the lighter
// of bare and mark, no optics, no noise — the picture of the part itself (--dose-png).
GreyImage part_view(const PartImage& part, const PartLook& look);

// A grey image of each pixel's marked share, row 0 at the top (0: bare, 255: marked): the part's
// own truth, for figures that compare a mark with its intended area.
GreyImage marked_share_view(const PartImage& part);

// The window's part as it is, at the raster's pixel or the smallest whole multiple of it that
// keeps both sides within max_side_px.
GreyImage part_picture(const DoseRaster& dose, const FieldWindow& window, const MarkResponse& response,
                       const PartLook& look, int max_side_px = 4096);

// Everything the beam dosed (whole raster tiles), grown by margin_mm; false when nothing was.
bool dosed_window(const DoseRaster& dose, double margin_mm, FieldWindow& window);

}  // namespace mark
