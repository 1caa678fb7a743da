// Identification from a picture (issue 24): the lag test pattern marked on a simulated head
// whose plant the fit is not told, photographed through the camera model (blur, noise, grain),
// written as a PNG and read back, recovers the plant's ramp lag within 5 % — the truth from the
// plant's own parameters in closed form (τ·scale; τ + latency outside the loop; τ − dead time
// inside it), not from the fit. A wrong pixel size, a mirrored picture or a bad pattern file is
// refused in one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "driver/sim/grey_png.hpp"
#include "marker/head/head_profile.hpp"
#include "marker/head/lag_fit.hpp"
#include "marker/head/lag_photo.hpp"
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
  // 20 mm at each speed, twice per axis, a tick at a time: Σ 2·2·20 / (v·10 µs).
  std::size_t want = 0;
  for (double v : p.speeds_mm_s) want += 4 * static_cast<std::size_t>(std::lround(20 / (v * 10e-6)));
  EXPECT_EQ(lit, want);
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
  EXPECT_DOUBLE_EQ(j["pixel_um"].get<double>(), 10.0);
  const auto fitted = test::run_cli({"head", "identify", "--from-image", picture, "--pixel-um", "10",
                                     "--pattern", pattern, "-o", profile, "--json"});
  ASSERT_EQ(fitted.code, 0) << fitted.err;
  const auto f = nlohmann::json::parse(fitted.out);
  EXPECT_NEAR(f["tau_s"].get<double>() / (1.1 * head_sl10().tau_s), 1.0, 0.05);
  const HeadProfile p = load_head_profile(profile);
  EXPECT_EQ(p.source, "image");
  EXPECT_EQ(p.model, ServoOrder::first);
  EXPECT_DOUBLE_EQ(p.tau_s, f["tau_s"].get<double>());
  EXPECT_DOUBLE_EQ(p.max_speed_mm_s, head_sl10().max_speed_mm_s);  // the preset's: not in a picture
  const auto used = test::run_cli({"mark", "AB", "--virtual-time", "--head-profile", profile, "--corner",
                                   "none", "--feed-forward", "--speed", "1000", "--json"});
  EXPECT_EQ(used.code, 0) << used.err;

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
