// The part as a camera sees it (SimScanner::picture_dose): each pulse of a pulsed source where it
// fired, so a fast stroke at a low frequency is a row of dots and an overlapping one a line,
// while the quality figures keep the time average. Checked against hand figures: the pulse pitch
// v / f, the dot a single pulse marks (its peak fluence p·√(2/π)/w times the line's), and the
// energy, which pulses and the time average must share.
#include <gtest/gtest.h>

#include <cmath>

#include "driver/sim/mark_response.hpp"
#include "driver/sim/part_image.hpp"
#include "driver/sim/sim_scanner.hpp"
#include "tests/driver/command_streams.hpp"

namespace mark {
namespace {

using test::Stream;

JobHeader pulsed_pen_header(double speed_mm_s, double frequency_khz, LaserSource source) {
  JobHeader h;
  DevicePen pen;
  pen.mark_speed_mm_s = speed_mm_s;
  pen.laser.frequency_khz = frequency_khz;
  pen.laser.source = source;
  h.pens.push_back(pen);
  h.lit_paths = {{{-3, 0}, {3, 0}}};
  return h;
}

// A settled jump to (−3, 0), a lit line to (3, 0) at v, the laser off while the beam catches up.
std::unique_ptr<SimScanner> marked_line(double v, double frequency_khz, LaserSource source = LaserSource::fiber) {
  SimScannerOptions o;
  o.head = head_sl10();
  auto sim = std::make_unique<SimScanner>(o);
  Stream s;
  s.step_to({-3, 0}, 300).move({3, 0}, v, true).hold(100, false);
  sim->begin_job(pulsed_pen_header(v, frequency_khz, source));
  sim->write(s.samples());
  sim->end_job();
  return sim;
}

// Marked runs along the line's centre between x = −1 and 1 mm (where the beam is at speed), at
// 2.5 µm steps, and whether every step was marked.
struct CentreLine {
  int runs = 0;
  bool all_marked = true;
};

CentreLine centre_line(const DoseRaster& dose) {
  const PartImage img = PartImage::render(dose, {-1.05, -0.05, 1.05, 0.05}, MarkResponse{}, 1);
  CentreLine c;
  bool was = false;
  for (double x = -1; x <= 1; x += 0.0025) {
    const bool m = img.share_at(x, 0) >= 0.5f;
    if (m && !was) ++c.runs;
    c.all_marked = c.all_marked && m;
    was = m;
  }
  return c;
}

// Width of the mark across the line at x.
double marked_width_um(const DoseRaster& dose, double x) {
  const PartImage img = PartImage::render(dose, {x - 0.01, -0.06, x + 0.01, 0.06}, MarkResponse{}, 1);
  int n = 0;
  for (double y = -0.06; y <= 0.06; y += 0.001) n += img.share_at(x, y) >= 0.5f;
  return n * 1.0;
}

TEST(PulsePicture, AFastStrokeAtALowFrequencyIsARowOfDots) {
  // 2000 mm/s at 20 kHz: pulses 100 µm apart. A pulse's peak fluence is p·√(2/π)/w = 4.0 times
  // the time-averaged line's (e²/2 of the threshold at this speed), so each marks a dot about
  // 2w·√(ln 14.7 / 2) = 46 µm wide and leaves 54 µm bare to the next: 20 dots in 2 mm.
  const auto sim = marked_line(2000, 20);
  ASSERT_NE(&sim->picture_dose(), &sim->dose());
  const CentreLine pulses = centre_line(sim->picture_dose());
  EXPECT_NEAR(pulses.runs, 20, 1);
  EXPECT_FALSE(pulses.all_marked);
  const CentreLine average = centre_line(sim->dose());
  EXPECT_EQ(average.runs, 1);
  EXPECT_TRUE(average.all_marked);
  // The same light either way: the totals differ by less than one pulse (1 × 50 µs).
  EXPECT_NEAR(sim->picture_dose().total(), sim->dose().total(), 50.01e-6);
  EXPECT_GT(sim->dose().total(), 0.5 * 6.0 / 2000);  // 6 mm at 2000 mm/s, full power
}

TEST(PulsePicture, OverlappingPulsesMarkTheLineTheTimeAverageMarks) {
  // 2000 mm/s at 100 kHz: pulses 20 µm apart on a 40 µm spot. The line is unbroken, and its
  // width where a pulse landed and between two is the time average's (32 µm at this speed)
  // within the scallop: ±6 µm.
  const auto sim = marked_line(2000, 100);
  const CentreLine pulses = centre_line(sim->picture_dose());
  EXPECT_EQ(pulses.runs, 1);
  EXPECT_TRUE(pulses.all_marked);
  const double average_um = marked_width_um(sim->dose(), 0);
  // Within a raster pixel (5 µm): the picture is laid on 5 µm pixels.
  EXPECT_NEAR(average_um, 2 * 20 * std::sqrt(std::log(std::exp(2.0) / 2) / 2), 5.0);
  for (double x = 0; x < 0.02; x += 0.005)
    EXPECT_NEAR(marked_width_um(sim->picture_dose(), x), average_um, 6.0) << "x " << x;
  EXPECT_NEAR(sim->picture_dose().total(), sim->dose().total(), 10.01e-6);  // one pulse
}

TEST(PulsePicture, AContinuousSourceOrAJobWithoutAPenIsPicturedAsTheTimeAverage) {
  // A CO2 source's frequency is its PWM carrier: continuous light.
  const auto co2 = marked_line(2000, 20, LaserSource::co2);
  EXPECT_EQ(&co2->picture_dose(), &co2->dose());
  // Samples without begin_job: no pen, no pulses to lay.
  SimScanner implicit;
  Stream s;
  s.step_to({-1, 0}, 300).move({1, 0}, 1000, true).hold(100, false);
  implicit.write(s.samples());
  EXPECT_EQ(&implicit.picture_dose(), &implicit.dose());
  EXPECT_GT(implicit.dose().total(), 0);
}

}  // namespace
}  // namespace mark
