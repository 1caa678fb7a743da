#include "driver/sim/dose_trail.hpp"

#include <algorithm>
#include <cmath>

namespace mark {

void DoseTrail::add(Vec2 a, Vec2 b, double dose) {
  if (!open_) {
    open_ = true;
    start_ = a;
    length_ = 0;
    dose_ = 0;
    have_mid_ = false;
  }
  last_ = b;
  const double len = norm(b - a);
  if (len <= 0) {
    dose_ += dose;
    return;
  }
  const double per_mm = dose / len;
  double u = 0;  // how far along a→b we are
  while (u < len) {
    const double take = std::min(spacing_ - length_, len - u);
    if (!have_mid_ && length_ + take >= 0.5 * spacing_) {
      mid_ = a + ((u + 0.5 * spacing_ - length_) / len) * (b - a);
      have_mid_ = true;
    }
    length_ += take;
    dose_ += take * per_mm;
    u += take;
    if (length_ >= spacing_ * (1 - 1e-9)) {
      raster_.deposit(mid_, dose_);
      start_ = a + (u / len) * (b - a);
      length_ = 0;
      dose_ = 0;
      have_mid_ = false;
    }
  }
}

void DoseTrail::flush() {
  if (open_ && dose_ > 0) raster_.deposit(have_mid_ ? mid_ : 0.5 * (start_ + last_), dose_);
  open_ = false;
  length_ = 0;
  dose_ = 0;
  have_mid_ = false;
}

}  // namespace mark
