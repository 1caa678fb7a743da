// EzCad's orientation by default: an asymmetric text captured on its way to the board decodes,
// with meerk40t's default galvo mapping, to the text unmirrored and untransposed; `marker frame`
// traces an upright F at the text's +x side. The decoder is meerk40t's, not ours: its View
// (meerk40t/core/view.py @5f68a45b: the lens square's destination corners, permuted by flip_x,
// flip_y and swap_xy, and the scene's corners mapped onto them) with its galvo device's defaults
// (balormk/device.py: 110 mm lens, flip_x off, flip_y on, swap_xy on), which meerk40t's own test
// vector pins to the bytes (scene (20, 20) mm → D174 2E8B). Its scene's y points down from the
// top left, as a screen shows the part.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "driver/lmc/capture_link.hpp"
#include "driver/lmc/lmc_device.hpp"
#include "fonts/catalog.hpp"
#include "marker/frame/orientation_mark.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/intended_strokes.hpp"
#include "marker/job/job.hpp"
#include "tests/marker/cli_runner.hpp"
#include "tests/marker/polyline_distance.hpp"

namespace mark {
namespace {

using test::distance_to;

struct Meerk40tView {
  double lens_mm = 110;
  bool flip_x = false, flip_y = true, swap_xy = true;

  // Board words → scene mm (x right, y down, origin at the lens's top left).
  std::array<double, 2> scene(double gx, double gy) const {
    const double g = 0xFFFF;  // galvo_range
    using P = std::array<double, 2>;
    std::array<P, 4> d{P{0, 0}, P{g, 0}, P{g, g}, P{0, g}};  // TL, TR, BR, BL
    if (flip_x) d = {d[1], d[0], d[3], d[2]};
    if (flip_y) d = {d[3], d[2], d[1], d[0]};
    if (swap_xy)
      for (P& p : d) std::swap(p[0], p[1]);
    // Matrix.map: scene TL (0,0) → d[0], TR (W,0) → d[1], BL (0,H) → d[3]; an affine map.
    const double ax = (d[1][0] - d[0][0]) / lens_mm, ay = (d[1][1] - d[0][1]) / lens_mm;
    const double bx = (d[3][0] - d[0][0]) / lens_mm, by = (d[3][1] - d[0][1]) / lens_mm;
    const double rx = gx - d[0][0], ry = gy - d[0][1], det = ax * by - ay * bx;
    return {(rx * by - ry * bx) / det, (ax * ry - ay * rx) / det};
  }
  // The scene as seen from above with y up from the lens centre: our field frame.
  Vec2 field(std::uint16_t gx, std::uint16_t gy) const {
    const auto s = scene(gx, gy);
    return {s[0] - lens_mm / 2, lens_mm / 2 - s[1]};
  }
};

// Every lit MarkTo end point of a capture, decoded by `view`.
std::vector<Vec2> lit_points(const std::string& capture, const Meerk40tView& view) {
  std::vector<Vec2> out;
  for (const lmc::CaptureRecord& rec : lmc::read_capture(capture))
    if (rec.packet)
      for (const lmc::Word& w : rec.words)
        if (w.opcode() == std::uint16_t(lmc::Op::MarkTo)) out.push_back(view.field(w.p(1), w.p(2)));
  return out;
}

double worst(const std::vector<std::vector<Vec2>>& intended, const std::vector<Vec2>& points) {
  double d = 0;
  for (const Vec2& p : points) d = std::max(d, distance_to(intended, p));
  return d;
}

TEST(LmcOrientation, ACaptureDecodesWithMeerk40tsDefaultsToTheTextUnmirrored) {
  // The view pinned to meerk40t's test vector first: its scene (20, 20) mm is D174 2E8B.
  const Meerk40tView view;
  const auto s = view.scene(0xD174, 0x2E8B);
  EXPECT_NEAR(s[0], 20, 0.002);
  EXPECT_NEAR(s[1], 20, 0.002);

  const auto path = test::fresh_temp_file("lmc_orientation_test", "f7r.lmc");
  JobSpec spec;
  spec.text = "F7R";  // no rotation or mirror maps it onto itself
  spec.font = open_font(kBuiltinFontName);
  spec.layout.height_mm = 4;
  spec.layout.base = Point(3, 5);  // off centre: a mirror would move it, too
  spec.head = head_sl10();
  spec.pen = pen_for_head(spec.head, CornerStrategy::blanking, 1000);
  lmc::LmcOptions o;  // the defaults: EzCad's axes
  o.init.settle_s = 0;
  JobResult r;
  {
    lmc::LmcDevice device(std::make_unique<lmc::CaptureLink>(path.string()), o);
    r = run_job(spec, JobOptions{}, device);
    ASSERT_EQ(r.outcome, JobOutcome::done);
  }
  const auto intended = intended_polylines(r.job.figure, 0.002);
  const auto points = lit_points(path.string(), view);
  ASSERT_GT(points.size(), 20u);
  // On the strokes to the board's truncation (1.7 µm a word) and the chords (5 µm).
  EXPECT_LE(worst(intended, points), 0.005 + 0.0025);
  std::printf("F7R through meerk40t's default view: %zu lit points within %.2f µm of the text\n", points.size(),
              worst(intended, points) * 1e3);

  // Read any other way, the same bytes are not the text: the test can tell.
  for (const auto& other : {Meerk40tView{110, false, false, true}, Meerk40tView{110, false, true, false},
                            Meerk40tView{110, true, true, true}, Meerk40tView{110, false, false, false}})
    EXPECT_GT(worst(intended, lit_points(path.string(), other)), 1.0)
        << "flip_x " << other.flip_x << " flip_y " << other.flip_y << " swap_xy " << other.swap_xy;
}

TEST(LmcOrientation, FrameTracesAnUprightFToTheRightOfTheText) {
  const auto path = test::fresh_temp_file("lmc_orientation_test", "frame.lmc");
  const auto r = test::run_cli({"frame", "F7R", "--height", "4", "--device", "lmc-capture:" + path.string(),
                                "--laps", "1", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  // The red pointer's moves, decoded by meerk40t's default view, in order.
  const Meerk40tView view;
  std::vector<Vec2> moves;
  for (const lmc::CaptureRecord& rec : lmc::read_capture(path.string()))
    if (rec.packet)
      for (const lmc::Word& w : rec.words)
        if (w.opcode() == std::uint16_t(lmc::Op::JumpTo)) moves.push_back(view.field(w.p(1), w.p(2)));
  ASSERT_GE(moves.size(), 6u + 4u);
  // The first six trace the F: up its stem, right along the top bar and back, down to the
  // middle, right along the middle bar.
  const Vec2 foot = moves[0], top = moves[1], bar = moves[2], back = moves[3], middle = moves[4], mid_bar = moves[5];
  const double h = top.y - foot.y;
  EXPECT_GE(h, 2.0);
  EXPECT_NEAR(top.x, foot.x, 0.003);                 // the stem is vertical
  EXPECT_NEAR(bar.y, top.y, 0.003);                  // the top bar horizontal,
  EXPECT_NEAR(bar.x - top.x, 0.6 * h, 0.003);        // and to the right: not mirrored
  EXPECT_NEAR(back.x, top.x, 0.003);
  EXPECT_NEAR(middle.y - foot.y, 0.55 * h, 0.003);   // the middle bar below the top: upright
  EXPECT_NEAR(mid_bar.x - middle.x, 0.45 * h, 0.003);
  // Beside the text, at its +x side: every other move (the box) lies to its left.
  for (std::size_t i = 6; i < moves.size(); ++i) EXPECT_LT(moves[i].x, foot.x) << i;
}

}  // namespace
}  // namespace mark
