// Identification from a picture (issue 24): the lag test pattern marked on a simulated head
// whose plant the fit is not told, photographed through the camera model (blur, noise, grain),
// written as a PNG and read back, recovers the plant's ramp lag within 5 % — the truth from the
// plant's own parameters in closed form (τ·scale; τ + latency outside the loop; τ − dead time
// inside it), not from the fit. A wrong pixel size, a mirrored picture or a bad pattern file is
// refused in one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <fstream>
#include <numbers>
#include <thread>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "driver/lmc/capture_link.hpp"
#include "driver/lmc/codec.hpp"
#include "driver/sim/grey_png.hpp"
#include "marker/cli/emulated_lmc_device.hpp"
#include "marker/head/head_profile.hpp"
#include "marker/head/lag_fit.hpp"
#include "marker/head/lag_photo.hpp"
#include "marker/head/lag_program.hpp"
#include "marker/job/board_watcher.hpp"
#include "marker/image/gray_image.hpp"
#include "tests/marker/cli_runner.hpp"

namespace mark {
namespace {

struct PlantCase {
  const char* name;
  Plant plant;
  double lag_s;  // the plant's ramp lag
};

// The picture as a user's file would give it: through PNG and the image reader.
GrayImage through_png(const GreyImage& picture) {
  return decode_png(encode_grey_png(picture), "lag.png");
}

LagFit fit_on(const SimScannerOptions& head, const LagPattern& pattern, const CameraSettings& camera = {}) {
  const GreyImage picture = photograph_lag_pattern(head, pattern, camera);
  return fit_lag_from_image(through_png(picture), picture.pixel_mm, pattern, "lag.png");
}

TEST(HeadLag, APictureOfThePatternRecoversAPlantThePlannerWasNotToldWithinFivePercent) {
  const HeadModel sl10 = head_sl10();
  Plant slow, fast, late, dead, rough;
  slow.tau_scale = 1.1;
  fast.tau_scale = 0.9;
  late.latency_us = 10;
  dead.dead_us = 10;
  rough.tau_scale = 1.1, rough.noise_um = 1, rough.resonance_hz = 10000;
  const PlantCase cases[] = {
      {"exact", {}, sl10.tau_s},
      {"tau_scale=1.1", slow, 1.1 * sl10.tau_s},
      {"tau_scale=0.9", fast, 0.9 * sl10.tau_s},
      {"latency_us=10", late, sl10.tau_s + 10e-6},
      {"dead_us=10", dead, sl10.tau_s - 10e-6},
      {"tau_scale=1.1,noise_um=1,resonance_hz=10000", rough, 1.1 * sl10.tau_s},
  };
  const LagPattern pattern = lag_pattern(sl10);
  for (const PlantCase& c : cases) {
    SimScannerOptions head;
    head.head = sl10;
    head.plant = c.plant;
    const LagFit fit = fit_on(head, pattern);
    EXPECT_NEAR(fit.tau_s / c.lag_s, 1.0, 0.05) << c.name << ": fitted " << fit.tau_s * 1e6 << " µs";
    EXPECT_NEAR(fit.tau_x_s / c.lag_s, 1.0, 0.05) << c.name;
    EXPECT_NEAR(fit.tau_y_s / c.lag_s, 1.0, 0.05) << c.name;
    EXPECT_LT(fit.rms_um, 3.0) << c.name;
    EXPECT_EQ(fit.pairs.size(), 2 * pattern.speeds_mm_s.size()) << c.name;
  }
}

TEST(HeadLag, SlowerHeadsAndASecondOrderHeadGiveTheirRampLag) {
  // SL14 saturates its acceleration at the fast lines' start; the end still lags v·τ. SA14 is
  // second order: its ramp lag is 2ζ/ωn.
  for (const HeadModel& h : {head_sl14(), head_cheap(), head_sa14()}) {
    SimScannerOptions head;
    head.head = h;
    const double lag = h.second_order ? 2 * h.zeta / h.omega_n() : h.tau_s;
    const LagFit fit = fit_on(head, lag_pattern(h));
    EXPECT_NEAR(fit.tau_s / lag, 1.0, 0.05) << h.name << ": fitted " << fit.tau_s * 1e6 << " µs";
  }
}

// The corners: an underdamped second-order head swings past a corner marked at speed and the
// mark bulges; the fit recovers ζ and ωn within 5 % of the plant's own (from its parameters:
// ωn = 2ζ/τ, ÷ tau_scale), a critically damped one (ζ = 1, no overshoot) from the bulge's shape,
// and every first-order plant — with a dead time, a resonance or noise — stays first order.
TEST(HeadLag, TheCornersTellASecondOrderHeadAndItsDampingWithinFivePercent) {
  struct OrderCase {
    const char* name;
    HeadModel head;
    Plant plant;
    double zeta;  // 0: first order
    double omega_n;
  };
  HeadModel sl10_half = head_sl10(), sl10_second = head_sl10();
  sl10_half.second_order = true, sl10_half.zeta = 0.5;
  sl10_second.second_order = true;
  Plant slow, noisy, dead, rough;
  slow.tau_scale = 1.1;
  noisy.noise_um = 1;
  dead.dead_us = 10;
  rough.resonance_hz = 10000, rough.noise_um = 1;
  const OrderCase cases[] = {
      {"SA14", head_sa14(), {}, head_sa14().zeta, head_sa14().omega_n()},
      {"SL10 second, zeta 0.5, tau_scale=1.1", sl10_half, slow, 0.5, sl10_half.omega_n() / 1.1},
      {"SL10 second, zeta 1, noise_um=1", sl10_second, noisy, 1.0, sl10_second.omega_n()},
      {"SL10 dead_us=10", head_sl10(), dead, 0, 0},
      {"SL10 resonance_hz=10000,noise_um=1", head_sl10(), rough, 0, 0},
      {"cheap", head_cheap(), {}, 0, 0},
  };
  for (const OrderCase& c : cases) {
    SimScannerOptions head;
    head.head = c.head;
    head.plant = c.plant;
    const LagFit fit = fit_on(head, lag_pattern(c.head));
    const CornerFit& k = fit.corners;
    ASSERT_EQ(k.corners.size(), 6u) << c.name;
    EXPECT_EQ(k.second_order, c.zeta > 0) << c.name << ": zeta " << k.zeta << ", rms first " << k.rms_first_um
                                          << " µm, second " << k.rms_second_um << " µm";
    if (c.zeta > 0) {
      EXPECT_NEAR(k.zeta / c.zeta, 1.0, 0.05) << c.name << ": zeta " << k.zeta;
      EXPECT_NEAR(k.omega_n_rad_s / c.omega_n, 1.0, 0.05) << c.name << ": omega_n " << k.omega_n_rad_s;
      EXPECT_LT(k.rms_second_um, 1.5) << c.name;
    } else {
      EXPECT_LT(k.rms_first_um, 1.5) << c.name;
      for (const CornerFigure& f : k.corners) EXPECT_LT(f.overshoot_um, 5.0) << c.name << " at " << f.speed_mm_s;
    }
    for (const CornerFigure& f : k.corners) EXPECT_GE(f.rows, 100) << c.name;
  }
  // The bulge scales with the speed (the loop is linear): 2000 against 500 mm/s is 4×.
  SimScannerOptions sa14;
  sa14.head = head_sa14();
  const CornerFit k = fit_on(sa14, lag_pattern(head_sa14())).corners;
  ASSERT_EQ(k.corners.size(), 6u);
  EXPECT_NEAR(k.corners[4].overshoot_um / k.corners[0].overshoot_um, 4.0, 0.4);  // 2000 vs 500 mm/s
}

TEST(HeadLag, ACoarserBlurredNoisierCameraStillFitsWithinFivePercent) {
  // A 20 µm pixel (half the spot), 40 µm of defocus and three times the read noise.
  SimScannerOptions head;
  head.plant.tau_scale = 1.1;
  CameraSettings camera;
  camera.pixel_um = 20;
  camera.defocus_um = 40;
  camera.read_noise_grey = 3;
  const LagFit fit = fit_on(head, lag_pattern(head.head), camera);
  EXPECT_NEAR(fit.tau_s / (1.1 * head.head.tau_s), 1.0, 0.05) << fit.tau_s * 1e6 << " µs";
}

// The picture turned by `deg` about its centre (bilinear), the corners it uncovers filled with
// the bare surface's grey (the picture's median): a part laid on a scanner not quite square.
GrayImage turned(const GrayImage& g, double deg) {
  std::vector<float> sorted = g.pixels;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const float bare = sorted[sorted.size() / 2];
  GrayImage out = g;
  const double a = deg * std::numbers::pi / 180, c = std::cos(a), s = std::sin(a);
  const double cx = (g.width - 1) / 2.0, cy = (g.height - 1) / 2.0;
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      const double u = cx + c * (x - cx) + s * (y - cy), v = cy - s * (x - cx) + c * (y - cy);
      const int u0 = static_cast<int>(std::floor(u)), v0 = static_cast<int>(std::floor(v));
      float value = bare;
      if (u0 >= 0 && v0 >= 0 && u0 + 1 < g.width && v0 + 1 < g.height) {
        const double fu = u - u0, fv = v - v0;
        value = static_cast<float>((1 - fu) * (1 - fv) * g.at(u0, v0) + fu * (1 - fv) * g.at(u0 + 1, v0) +
                                   (1 - fu) * fv * g.at(u0, v0 + 1) + fu * fv * g.at(u0 + 1, v0 + 1));
      }
      out.pixels[static_cast<std::size_t>(y) * g.width + x] = value;
    }
  return out;
}

TEST(HeadLag, APictureTurnedByADegreeStillFitsWithinFivePercent) {
  SimScannerOptions head;
  head.plant.tau_scale = 1.1;
  const LagPattern pattern = lag_pattern(head.head);
  const GreyImage picture = photograph_lag_pattern(head, pattern);
  for (double deg : {1.0, -1.0}) {
    const LagFit fit = fit_lag_from_image(turned(through_png(picture), deg), picture.pixel_mm, pattern, "scan.png");
    EXPECT_NEAR(fit.tau_s / (1.1 * head.head.tau_s), 1.0, 0.05) << deg << "°: " << fit.tau_s * 1e6 << " µs";
    EXPECT_FALSE(fit.corners.second_order) << deg << "°: zeta " << fit.corners.zeta;
  }
  // The corners' fit takes the turn out with the long lines' tilt: SA14's ζ within 5 % still.
  SimScannerOptions sa14;
  sa14.head = head_sa14();
  const LagPattern sa14_pattern = lag_pattern(sa14.head);
  const GreyImage sa14_picture = photograph_lag_pattern(sa14, sa14_pattern);
  for (double deg : {1.0, -1.0}) {
    const LagFit fit =
        fit_lag_from_image(turned(through_png(sa14_picture), deg), sa14_picture.pixel_mm, sa14_pattern, "scan.png");
    EXPECT_TRUE(fit.corners.second_order) << deg << "°";
    EXPECT_NEAR(fit.corners.zeta / sa14.head.zeta, 1.0, 0.05) << deg << "°: zeta " << fit.corners.zeta;
  }
}

TEST(HeadLag, AWrongPixelSizeAMirroredPictureOrAnEmptyOneIsRefused) {
  SimScannerOptions head;
  const LagPattern pattern = lag_pattern(head.head);
  const GreyImage picture = photograph_lag_pattern(head, pattern);
  const GrayImage g = through_png(picture);
  try {
    fit_lag_from_image(g, picture.pixel_mm * 1.2, pattern, "scan.png");
    FAIL() << "a wrong pixel size was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'scan.png': the marks span"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("a wrong --pixel-um"), std::string::npos) << e.what();
  }
  GrayImage mirrored = g;
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x)
      mirrored.pixels[static_cast<std::size_t>(y) * g.width + x] = g.at(g.width - 1 - x, y);
  EXPECT_THROW(fit_lag_from_image(mirrored, picture.pixel_mm, pattern, "scan.png"), InputError);
  GrayImage blank = g;
  std::fill(blank.pixels.begin(), blank.pixels.end(), 0.6f);
  try {
    fit_lag_from_image(blank, picture.pixel_mm, pattern, "scan.png");
    FAIL() << "a blank picture was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no marks"), std::string::npos) << e.what();
  }
  // A picture of the lines alone (a pattern marked before the corners were added), fitted with
  // a pattern file that has them: the first corner is named, not a nonsense ζ.
  LagPattern lines_only = pattern;
  lines_only.corners.clear();
  const GreyImage old = photograph_lag_pattern(head, lines_only);
  try {
    fit_lag_from_image(through_png(old), old.pixel_mm, pattern, "old.png");
    FAIL() << "a picture without its corners was fitted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "'old.png': the x corner at 500 mm/s has no mark where its first leg should be: "
                                     "not a picture of this pattern, or turned by more than 1.5°");
  }
}

TEST(HeadLag, ThePatternStaysInItsExtentAndLightsOnlyAlongItsLines) {
  const LagPattern p = lag_pattern(head_sl10());
  ASSERT_EQ(p.speeds_mm_s, (std::vector<double>{500, 1000, 2000, 3000, 4000}));
  ASSERT_EQ(p.lines.size(), 20u);
  const Vec2 lo = p.min(), hi = p.max();
  EXPECT_NEAR(hi.x - lo.x, 20 + 3 + 9, 1e-9);
  EXPECT_NEAR(hi.y - lo.y, 20, 1e-9);
  std::size_t lit = 0;
  for (const ScanSample& s : lag_pattern_samples(p, 10e-6)) {
    EXPECT_GE(s.x_mm, lo.x - 1e-4);
    EXPECT_LE(s.x_mm, hi.x + 1e-4);
    EXPECT_GE(s.y_mm, lo.y - 1e-4);
    EXPECT_LE(s.y_mm, hi.y + 1e-4);
    lit += s.laser;
  }
  // 20 mm at each speed, twice per axis, a tick at a time: Σ 2·2·20 / (v·10 µs); and two
  // corners per corner speed, each two 4 mm legs.
  ASSERT_EQ(p.corner_speeds_mm_s, (std::vector<double>{500, 1000, 2000}));
  ASSERT_EQ(p.corners.size(), 6u);
  std::size_t want = 0;
  for (double v : p.speeds_mm_s) want += 4 * static_cast<std::size_t>(std::lround(20 / (v * 10e-6)));
  for (double v : p.corner_speeds_mm_s) want += 2 * 2 * static_cast<std::size_t>(std::lround(4 / (v * 10e-6)));
  EXPECT_EQ(lit, want);
  // The corners lie below the x rows, clear of them by 1.5 mm, and turn a right angle.
  for (const LagCorner& c : p.corners) {
    EXPECT_LE(std::max(c.end.y, c.corner.y) + 1.5, hi.y - 9 + 1e-9);
    EXPECT_NEAR(dot(c.corner - c.start, c.end - c.corner), 0, 1e-12);
    EXPECT_NEAR(norm(c.corner - c.start), 4, 1e-12);
  }
  // A head whose 40 % speed is under 500 mm/s gets slower lines; a field too small is refused.
  HeadModel slow = head_sl10();
  slow.max_speed_mm_s = 1000;
  EXPECT_EQ(lag_pattern(slow).speeds_mm_s, (std::vector<double>{50, 100, 250}));
  HeadModel small = head_sl10();
  small.field_mm = 20;
  EXPECT_THROW(lag_pattern(small), InputError);
}

TEST(HeadLag, ThePatternFileRoundTripsAndABadOneIsRefusedNamingTheKey) {
  const LagPattern p = lag_pattern(head_sl10(), {5, -3});
  const LagPattern back = parse_lag_pattern(lag_pattern_json(p), "p.json");
  ASSERT_EQ(back.lines.size(), p.lines.size());
  for (std::size_t i = 0; i < p.lines.size(); ++i) {
    EXPECT_NEAR(back.lines[i].start.x, p.lines[i].start.x, 1e-9);
    EXPECT_NEAR(back.lines[i].end.y, p.lines[i].end.y, 1e-9);
    EXPECT_EQ(back.lines[i].forward, p.lines[i].forward);
  }
  ASSERT_EQ(back.corners.size(), p.corners.size());
  for (std::size_t i = 0; i < p.corners.size(); ++i) {
    EXPECT_NEAR(norm(back.corners[i].corner - p.corners[i].corner), 0, 1e-9);
    EXPECT_EQ(back.corners[i].speed_mm_s, p.corners[i].speed_mm_s);
  }
  // A pattern file from before the corners has none, and still fits (first order).
  nlohmann::json old = nlohmann::json::parse(lag_pattern_json(p));
  old.erase("corner_leg_mm"), old.erase("corner_speeds_mm_s");
  EXPECT_TRUE(parse_lag_pattern(old.dump(), "old.json").corners.empty());
  auto refusal = [](const std::string& text) {
    try {
      parse_lag_pattern(text, "p.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string head = R"({"format": "marker lag pattern", "version": 1, "centre_mm": [0, 0], )";
  EXPECT_EQ(refusal(head + R"("length_mm": 0.5, "pitch_mm": 1, "gap_mm": 3, "speeds_mm_s": [1, 2, 3]})"),
            "lag pattern p.json: 'length_mm' is 0.5, outside 1 to 1000");
  EXPECT_EQ(refusal(head + R"("length_mm": 20, "pitch_mm": 1, "gap_mm": 3, "speeds_mm_s": [1, 2]})"),
            "lag pattern p.json: 'speeds_mm_s' must list 3 to 20 speeds");
  EXPECT_EQ(refusal(R"({"format": 7})"), "lag pattern p.json: 'format' must be \"marker lag pattern\"");
  EXPECT_EQ(refusal(R"({"format": "marker lag pattern", "version": "1"})"), "lag pattern p.json: 'version' must be 1");
  EXPECT_NE(refusal("[1,").find("lag pattern p.json: not JSON ("), std::string::npos);
  EXPECT_EQ(refusal("[1]"), "lag pattern p.json: must be one JSON object");
  const std::string lines = head + R"("length_mm": 20, "pitch_mm": 1, "gap_mm": 3, "speeds_mm_s": [500, 1000, 2000], )";
  EXPECT_EQ(refusal(lines + R"("corner_leg_mm": 40, "corner_speeds_mm_s": [500]})"),
            "lag pattern p.json: 'corner_leg_mm' is 40, outside 1 to 20");
  EXPECT_EQ(refusal(lines + R"("corner_leg_mm": 4})"),
            "lag pattern p.json: 'corner_speeds_mm_s' must list 1 to 10 speeds with 'corner_leg_mm'");
  EXPECT_EQ(refusal(lines + R"("corner_leg_mm": 4, "corner_speeds_mm_s": [500, 1e6]})"),
            "lag pattern p.json: 'corner_speeds_mm_s' holds a value outside 1 to 100000 mm/s");
  EXPECT_EQ(refusal(lines + R"("corner_leg_mm": 4, "corner_speeds_mm_s": [500, 1000, 2000, 500]})"),
            "lag pattern p.json: the corners ('corner_leg_mm', 'corner_speeds_mm_s') do not fit below the x lines");
  EXPECT_EQ(refusal(lines + R"("corner_leg_mm": 4, "corner_speeds_mm_s": [700]})"),
            "lag pattern p.json: 'corner_speeds_mm_s' holds 700 mm/s, none of 'speeds_mm_s'");
}

// The board's program: one pen per speed with the power in proportion and every delay zero (a
// delay would read as lag), the holds split at the board's longest dwell, and a pattern outside
// the board's field or faster than it marks refused before anything is sent.
TEST(HeadLag, TheBoardProgramHasOnePenPerSpeedItsPowerInProportionAndNoDelay) {
  const LagPattern pattern = lag_pattern(head_sl10());
  DeviceDescription board;
  board.name = "board";
  board.level = DeviceLevel::commands;
  board.max_dwell_s = 5e-3;  // the 12 ms settle goes as three dwells, the 2 ms hold as one
  LaserSettings laser;
  laser.power_pct = 80;
  const LagProgram p = lag_pattern_program(pattern, laser, board);
  ASSERT_EQ(p.header.pens.size(), pattern.speeds_mm_s.size());
  for (std::size_t i = 0; i < p.header.pens.size(); ++i) {
    const DevicePen& pen = p.header.pens[i];
    EXPECT_DOUBLE_EQ(pen.mark_speed_mm_s, pattern.speeds_mm_s[i]);
    EXPECT_NEAR(pen.laser.power_pct, 80 * pattern.speeds_mm_s[i] / 4000, 1e-9);
    EXPECT_EQ(pen.laser_on_delay_s + pen.laser_off_delay_s + pen.jump_delay_s + pen.mark_delay_s + pen.polygon_delay_s,
              0.0);
  }
  std::size_t marks = 0, dwells = 0, pens = 0;
  double held_s = 0;
  for (const DeviceCommand& c : p.commands) {
    marks += c.op == DeviceOp::mark;
    pens += c.op == DeviceOp::pen;
    if (c.op != DeviceOp::dwell) continue;
    ++dwells;
    EXPECT_FALSE(c.laser);
    EXPECT_LE(c.dwell_s, board.max_dwell_s + 1e-12);
    held_s += c.dwell_s;
  }
  // A mark per line, two per corner (through it without a stop); each axis's lines run through
  // the speeds once, then the corners, two at each corner speed.
  const std::size_t paths = pattern.lines.size() + pattern.corners.size();
  EXPECT_EQ(marks, pattern.lines.size() + 2 * pattern.corners.size());
  EXPECT_EQ(pens, 2 * pattern.speeds_mm_s.size() + pattern.corner_speeds_mm_s.size());
  EXPECT_EQ(dwells, 4 * paths);
  EXPECT_NEAR(held_s, static_cast<double>(paths) * (kLagJumpSettle_s + kLagAfterLine_s), 1e-9);
  EXPECT_EQ(p.header.lit_paths.size(), paths);

  DeviceDescription small = board;
  small.field_mm = 20;
  EXPECT_THROW(
      {
        try {
          lag_pattern_program(pattern, laser, small);
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("outside the 20 mm field of board"), std::string::npos) << e.what();
          throw;
        }
      },
      InputError);
  DeviceDescription slow = board;
  slow.max_speed_mm_s = 3000;
  EXPECT_THROW(lag_pattern_program(pattern, laser, slow), InputError);
}

// The whole LMC path without a board — the program as the real driver's list packets, the
// emulated board running them on its own clock, its output into a simulated head whose plant
// the fit is not told — photographed and fitted: the plant's ramp lag within 5 %.
TEST(HeadLag, MarkedThroughTheEmulatedBoardThePictureRecoversThePlantLag) {
  const HeadModel sl10 = head_sl10();
  Plant slow, dead;
  slow.tau_scale = 1.1;
  dead.dead_us = 10, dead.noise_um = 1;
  const PlantCase cases[] = {{"tau_scale=1.1", slow, 1.1 * sl10.tau_s}, {"dead_us=10,noise_um=1", dead, sl10.tau_s - 10e-6}};
  const LagPattern pattern = lag_pattern(sl10);
  for (const PlantCase& c : cases) {
    SimScannerOptions head;
    head.head = sl10;
    head.plant = c.plant;
    lmc::LmcOptions o;
    o.field_mm = sl10.field_mm;
    o.init.settle_s = 0;
    cli::EmulatedLmcDevice board(head, o, *lmc::parse_lmc_spec("lmc-emulated"), true);
    const LagProgram program = lag_pattern_program(pattern, LaserSettings{}, board.describe());
    const DeviceReport report = run_board_program(board, program.header, program.commands, nullptr);
    ASSERT_EQ(report.outcome, DeviceState::done) << c.name;
    EXPECT_EQ(report.commands_done, program.commands.size()) << c.name;
    const GreyImage picture = photograph_lag_dose(board.scanner().dose(), pattern);
    const LagFit fit = fit_lag_from_image(through_png(picture), picture.pixel_mm, pattern, "board.png");
    EXPECT_NEAR(fit.tau_s / c.lag_s, 1.0, 0.05) << c.name << ": fitted " << fit.tau_s * 1e6 << " µs";
    EXPECT_NEAR(fit.tau_x_s / c.lag_s, 1.0, 0.05) << c.name;
    EXPECT_NEAR(fit.tau_y_s / c.lag_s, 1.0, 0.05) << c.name;
  }
}

// Ctrl-C on the board: the stop aborts it (laser off) and the report says how far it got — a
// stop before the first command sends none; one in the middle (the board in real time, the
// stop once 30 commands were sent) leaves the rest unmarked.
TEST(HeadLag, AStopAbortsTheBoardWithTheLaserOffAndSaysHowFarItGot) {
  const LagPattern pattern = lag_pattern(head_sl10());
  SimScannerOptions head;
  head.head = head_sl10();
  lmc::LmcOptions o;
  o.init.settle_s = 0;
  const auto whole = lag_pattern_samples(pattern, head.tick_s).size();  // the pattern run through
  for (const bool at_once : {true, false}) {
    cli::EmulatedLmcDevice board(head, o, *lmc::parse_lmc_spec("lmc-emulated"), false);
    const LagProgram program = lag_pattern_program(pattern, LaserSettings{}, board.describe());
    StopFlag stop;
    if (at_once) stop.request();
    std::atomic<bool> ended{false};
    std::thread op([&] {
      // Also ends when the job did (it then fails below, naming the outcome): never waits for ever.
      while (!ended.load() && board.status().progress < 30) std::this_thread::sleep_for(std::chrono::milliseconds(1));
      stop.request();
    });
    const DeviceReport report = run_board_program(board, program.header, program.commands, &stop);
    ended.store(true);
    op.join();
    ASSERT_EQ(report.outcome, DeviceState::aborted) << (at_once ? "at once" : "mid-way") << ": "
                                                    << to_string(report.outcome);
    EXPECT_FALSE(board.status().laser_on);
    EXPECT_FALSE(board.scanner().laser_commanded());
    // The board says only what it was sent (docs/lmc.md); what it ran shows in the scanner's clock.
    if (at_once) {
      EXPECT_EQ(report.commands_done, 0u);
    }
    EXPECT_LT(board.scanner().samples(), 0.8 * static_cast<double>(whole));
  }
}

// On a real board (here its bytes captured): the pattern file and no picture (the user scans
// the part); on the wire one MarkTo per line, the power words in proportion to the speed words
// and zero laser delays.
TEST(HeadLagCli, TestPatternOnABoardSendsOneMarkPerLineWithPowerInProportion) {
  const auto dir = test::fresh_temp_dir("head_lag_board");
  const std::string pattern = (dir / "p.json").string(), picture = (dir / "p.png").string(),
                    capture = (dir / "p.lmc").string();
  const auto r = test::run_cli(
      {"head", "test-pattern", "--device", "lmc-capture:" + capture, "--power", "60", "-o", pattern, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["device"], "lmc 00000000");
  EXPECT_FALSE(j.contains("picture"));
  EXPECT_FALSE(std::filesystem::exists(picture));
  EXPECT_NO_THROW(load_lag_pattern(pattern));
  std::size_t marks = 0;
  std::vector<double> powers;
  for (const lmc::CaptureRecord& rec : lmc::read_capture(capture))
    for (const lmc::Word& w : rec.words) {
      const auto op = static_cast<lmc::Op>(w.opcode());
      marks += op == lmc::Op::MarkTo;
      if (op == lmc::Op::MarkCurrent) powers.push_back(100.0 * w.p(1) / 4095);
      if (op == lmc::Op::LaserOnDelay || op == lmc::Op::LaserOffDelay) {
        EXPECT_EQ(w.p(1), 0) << "a laser delay";
      }
    }
  EXPECT_EQ(marks, 20u + 2 * 6);  // the lines, and the corners' two legs
  std::vector<double> expected;
  for (double v : {500.0, 1000.0, 2000.0, 3000.0, 4000.0}) expected.push_back(60 * v / 4000);
  std::sort(powers.begin(), powers.end());
  powers.erase(std::unique(powers.begin(), powers.end(), [](double a, double b) { return std::abs(a - b) < 0.05; }),
               powers.end());
  ASSERT_EQ(powers.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(powers[i], expected[i], 0.03);

  // At 30 kHz the 4000 mm/s line is a row of dots 133 µm apart, which the fit cannot follow
  // (the command says so); without --frequency it picks 200 kHz, where they overlap.
  const auto dotted = test::run_cli({"head", "test-pattern", "--device", "lmc-emulated", "--virtual-time", "-o",
                                     pattern, "--picture", picture, "--frequency", "30", "--json"});
  ASSERT_EQ(dotted.code, 0) << dotted.err;
  EXPECT_NE(dotted.err.find("pulses 133 µm apart on a 40 µm spot"), std::string::npos) << dotted.err;
  const auto emulated = test::run_cli({"head", "test-pattern", "--device", "lmc-emulated", "--virtual-time",
                                       "--plant", "tau_scale=0.9", "-o", pattern, "--picture", picture});
  ASSERT_EQ(emulated.code, 0) << emulated.err;
  EXPECT_EQ(emulated.err.find("warning"), std::string::npos) << emulated.err;
  EXPECT_NE(emulated.err.find("marker: pulses at 200 kHz, 20 µm apart on the fastest line (4000 mm/s, 40 µm spot)"),
            std::string::npos)
      << emulated.err;
  const auto fitted = test::run_cli({"head", "identify", "--from-image", picture, "--pixel-um", "10", "--pattern",
                                     pattern, "-o", (dir / "h.json").string(), "--json"});
  ASSERT_EQ(fitted.code, 0) << fitted.err;
  EXPECT_NEAR(nlohmann::json::parse(fitted.out)["tau_s"].get<double>() / (0.9 * head_sl10().tau_s), 1.0, 0.05);

  const auto sim_power = test::run_cli({"head", "test-pattern", "--power", "50", "-o", pattern, "--picture", picture});
  EXPECT_EQ(sim_power.code, 1);
  EXPECT_NE(sim_power.err.find("--power applies to a board (--device lmc…)"), std::string::npos) << sim_power.err;
  const std::string unused = (dir / "unused.lmc").string();
  const auto real_plant = test::run_cli({"head", "test-pattern", "--device", "lmc-capture:" + unused, "--plant",
                                         "tau_scale=1.1", "-o", pattern});
  EXPECT_EQ(real_plant.code, 1);
  EXPECT_NE(real_plant.err.find("a real board drives its own head"), std::string::npos) << real_plant.err;
  const auto real_picture = test::run_cli({"head", "test-pattern", "--device", "lmc-capture:" + unused, "--picture",
                                           picture, "-o", pattern});
  EXPECT_EQ(real_picture.code, 1);
  EXPECT_NE(real_picture.err.find("--picture: a real board's mark is on the part"), std::string::npos)
      << real_picture.err;
  EXPECT_FALSE(std::filesystem::exists(unused));  // refused before the capture began
}

TEST(HeadLagCli, TestPatternThenIdentifyFromImageWritesAProfileTheMarkCommandTakes) {
  const auto dir = test::fresh_temp_dir("head_lag_cli");
  const std::string pattern = (dir / "p.json").string(), picture = (dir / "p.png").string(),
                    profile = (dir / "h.json").string();
  const auto marked = test::run_cli({"head", "test-pattern", "--plant", "tau_scale=1.1", "-o", pattern,
                                     "--picture", picture, "--json"});
  ASSERT_EQ(marked.code, 0) << marked.err;
  const auto j = nlohmann::json::parse(marked.out);
  EXPECT_EQ(j["lines"], 20);
  EXPECT_EQ(j["corners"], 6);
  EXPECT_DOUBLE_EQ(j["pixel_um"].get<double>(), 10.0);
  const auto fitted = test::run_cli({"head", "identify", "--from-image", picture, "--pixel-um", "10",
                                     "--pattern", pattern, "-o", profile, "--json"});
  ASSERT_EQ(fitted.code, 0) << fitted.err;
  const auto f = nlohmann::json::parse(fitted.out);
  EXPECT_NEAR(f["tau_s"].get<double>() / (1.1 * head_sl10().tau_s), 1.0, 0.05);
  EXPECT_EQ(f["model"], "first");  // the corners show no overshoot
  EXPECT_EQ(f["corners"].size(), 6u);
  const HeadProfile p = load_head_profile(profile);
  EXPECT_EQ(p.source, "image");
  EXPECT_EQ(p.model, ServoOrder::first);
  EXPECT_DOUBLE_EQ(p.tau_s, f["tau_s"].get<double>());
  EXPECT_DOUBLE_EQ(p.max_speed_mm_s, head_sl10().max_speed_mm_s);  // the preset's: not in a picture
  const auto used = test::run_cli({"mark", "AB", "--virtual-time", "--head-profile", profile, "--corner",
                                   "none", "--feed-forward", "--speed", "1000", "--json"});
  EXPECT_EQ(used.code, 0) << used.err;

  // A second-order head's corners give a second-order profile, which mark plans with.
  ASSERT_EQ(test::run_cli({"head", "test-pattern", "--head", "SA14", "-o", pattern, "--picture", picture}).code, 0);
  const auto sa14 = test::run_cli({"head", "identify", "--from-image", picture, "--pixel-um", "10", "--pattern",
                                   pattern, "--head", "SA14", "-o", profile});
  ASSERT_EQ(sa14.code, 0) << sa14.err;
  EXPECT_NE(sa14.out.find("model: second order"), std::string::npos) << sa14.out;
  const HeadProfile q = load_head_profile(profile);
  EXPECT_EQ(q.model, ServoOrder::second);
  EXPECT_NEAR(q.zeta / head_sa14().zeta, 1.0, 0.05);
  EXPECT_NEAR(q.lag_s() / q.tau_s, 1.0, 1e-12);  // the lines' ramp lag, kept as 2ζ/ωn
  // Planned with it, feed-forward marks as with the head's own (datasheet) model, within a
  // micrometre; the same ramp lag as a first-order model is off by a quarter of a millimetre.
  auto deviation_um = [&](const std::vector<std::string>& model) {
    std::vector<std::string> args{"mark", "AB", "--virtual-time", "--head", "SA14", "--corner", "none",
                                  "--feed-forward", "--speed", "3000", "--frequency", "200", "--json"};
    args.insert(args.end(), model.begin(), model.end());
    const auto r = test::run_cli(args);
    EXPECT_EQ(r.code, 0) << r.err;
    return r.code == 0 ? nlohmann::json::parse(r.out)["quality"]["max_deviation_um"].get<double>() : 1e9;
  };
  const std::string first = (dir / "first.json").string();
  auto as_first = nlohmann::json::parse(std::ifstream(profile));
  as_first["model"] = "first";
  std::ofstream(first) << as_first.dump();
  const double own = deviation_um({}), fitted_um = deviation_um({"--head-profile", profile});
  EXPECT_NEAR(fitted_um, own, 1.0);
  EXPECT_GT(deviation_um({"--head-profile", first}), 10 * fitted_um);

  const auto no_pixel = test::run_cli({"head", "identify", "--from-image", picture, "--pattern", pattern});
  EXPECT_EQ(no_pixel.code, 1);
  EXPECT_NE(no_pixel.err.find("--from-image needs --pixel-um"), std::string::npos) << no_pixel.err;
  const auto second = test::run_cli({"head", "identify", "--from-image", picture, "--pixel-um", "10",
                                     "--pattern", pattern, "--head-model", "second"});
  EXPECT_EQ(second.code, 1);
  EXPECT_NE(second.err.find("--head-model and --head-zeta do not apply with --from-image"), std::string::npos)
      << second.err;
  const auto stray = test::run_cli({"head", "identify", "--pixel-um", "10"});
  EXPECT_EQ(stray.code, 1);
  EXPECT_NE(stray.err.find("--pattern and --pixel-um go with --from-image"), std::string::npos) << stray.err;
}

}  // namespace
}  // namespace mark
