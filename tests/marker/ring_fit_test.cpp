// A mirror resonance identified from a picture (marker/head/ring_fit.hpp): the lag test pattern
// marked on a simulated head with a resonance the fit is not told, photographed through the
// camera model and read back through PNG, gives the resonance's frequency within 5 %; a head
// without one — or one whose only differences are the lag, a dead time or noise — gives none.
// The truth is the plant's own parameter, not the fit's.
#include <gtest/gtest.h>

#include <cstdio>

#include "driver/sim/grey_png.hpp"
#include "marker/cli/plant_option.hpp"
#include "marker/head/lag_fit.hpp"
#include "marker/head/lag_photo.hpp"
#include "marker/image/gray_image.hpp"

namespace mark {
namespace ring_test {

RingFit ring_on(const char* plant) {
  SimScannerOptions head;
  head.head = head_sl10();
  head.plant = cli::parse_plant_option(plant);
  const LagPattern pattern = lag_pattern(head.head);
  const GreyImage picture = photograph_lag_pattern(head, pattern);
  const GrayImage read = decode_png(encode_grey_png(picture), "lag.png");
  const LagFit fit = fit_lag_from_image(read, picture.pixel_mm, pattern, "lag.png");
  const RingFit& r = fit.corners.ring;
  std::printf("%-45s seen %d  %7.0f Hz  zeta %.3f  amplitude %.2f um  rms %.2f -> %.2f um\n", plant, r.seen,
              r.frequency_hz, r.zeta, r.amplitude_um, r.rms_before_um, r.rms_after_um);
  return r;
}

TEST(RingFit, APictureGivesAHiddenResonanceWithinFivePercent) {
  for (const auto& [plant, hz] : {std::pair{"resonance_hz=10000", 10000.0},
                                  std::pair{"resonance_hz=13500,resonance_zeta=0.04", 13500.0},
                                  std::pair{"tau_scale=1.1,resonance_hz=9000,noise_um=0.5", 9000.0},
                                  std::pair{"resonance_hz=11000,noise_um=1", 11000.0}}) {
    const RingFit r = ring_on(plant);
    EXPECT_TRUE(r.seen) << plant;
    EXPECT_NEAR(r.frequency_hz / hz, 1.0, 0.05) << plant << ": " << r.frequency_hz << " Hz";
  }
}

TEST(RingFit, AHeadWithoutOneGivesNone) {
  // (latency_us=10, backemf_speed=12000 and resonance_hz=7000 gave the same answers: none; 6974 Hz.)
  for (const char* plant : {"", "tau_scale=1.1", "dead_us=10", "noise_um=1"}) {
    const RingFit r = ring_on(plant);
    EXPECT_FALSE(r.seen) << plant << ": " << r.frequency_hz << " Hz, " << r.amplitude_um << " µm";
  }
}

}  // namespace ring_test
}  // namespace mark
