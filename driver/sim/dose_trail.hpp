#pragma once
// Lays the dose of a moving beam into a raster in even steps along its path: the dose of every
// half-pixel stretch of path goes to that stretch's midpoint. The simulator's sub-steps are
// often far shorter than a pixel (1 µm at 1 m/s), so depositing per sub-step would cost several
// bilinear splats per pixel of path for nothing; a fast beam still gets one splat per half pixel,
// so no gaps. Dose given while the beam stands still collects until it moves on or flush().
#include "driver/sim/dose_raster.hpp"
#include "driver/vec2.hpp"

namespace mark {

class DoseTrail {
 public:
  explicit DoseTrail(DoseRaster& raster)
      : raster_(raster), spacing_(0.5 * raster.pixel_mm()) {}

  // The beam moved a → b (a is where the previous piece ended) and `dose` fell along the way.
  void add(Vec2 a, Vec2 b, double dose);
  // Deposit whatever has collected (end of a lit run, end of a block).
  void flush();

 private:
  DoseRaster& raster_;
  double spacing_;
  double length_ = 0;     // path length of the current stretch
  double dose_ = 0;       // dose collected over it
  Vec2 start_{0, 0};      // where the stretch began
  Vec2 mid_{0, 0};        // its midpoint, once length_ ≥ spacing/2
  Vec2 last_{0, 0};
  bool open_ = false;     // a stretch is in progress
  bool have_mid_ = false;
};

}  // namespace mark
