// The locus generator: constant speed along lines, arcs and ellipses, exact end points, no
// accumulated time or length error, streaming in arbitrary blocks.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "base/numbers.hpp"
#include "marker/locus/locus_generator.hpp"
#include "marker/locus/path_walker.hpp"

namespace mark {
namespace {

constexpr double kLocusTick = 10e-6;
std::vector<ScanSample> run(const std::vector<Command>& commands, std::size_t block = 4096,
                            double tick = kLocusTick) {
  LocusGenerator gen(commands, tick);
  std::vector<ScanSample> all;
  std::vector<ScanSample> buf(block);
  while (std::size_t n = gen.generate(buf.data(), buf.size())) all.insert(all.end(), buf.begin(), buf.begin() + n);
  EXPECT_TRUE(gen.done());
  EXPECT_EQ(all.size(), gen.samples_written());
  return all;
}

Point pt(const ScanSample& s) { return {s.x_mm, s.y_mm}; }

TEST(Locus, LineAtConstantSpeedEndsOnItsEndPoint) {
  // 10 mm at 1000 mm/s with a 10 µs tick: 1000 steps of 10 µm.
  const auto s = run({Command::mark(Element::line({-5, 1}, {5, 1}), 1000, CommandRole::stroke)});
  ASSERT_EQ(s.size(), 1000u);
  EXPECT_NEAR(s[0].x_mm, -4.99, 1e-6);
  for (std::size_t i = 1; i < s.size(); ++i) {
    EXPECT_NEAR((pt(s[i]) - pt(s[i - 1])).norm(), 0.01, 1e-6);
    EXPECT_TRUE(s[i].laser);
  }
  EXPECT_EQ(s.back().x_mm, 5.0f);
  EXPECT_EQ(s.back().y_mm, 1.0f);
}

TEST(Locus, JumpAtJumpSpeedWithLaserOff) {
  const auto s = run({Command::jump({0, 0}, {3, 4}, 5000)});  // 5 mm at 5 m/s: 100 ticks
  ASSERT_EQ(s.size(), 100u);
  for (const ScanSample& x : s) EXPECT_FALSE(x.laser);
  EXPECT_NEAR((pt(s[1]) - pt(s[0])).norm(), 0.05, 1e-6);
  EXPECT_EQ(pt(s.back()), Point(3, 4));
}

TEST(Locus, CircularArcUniformOnTheCircle) {
  const Element arc = Element::arc({1, 2}, 0.5, 0.3, -4.0);  // clockwise, 2 mm long
  const auto s = run({Command::mark(arc, 400, CommandRole::stroke)});  // 4 µm steps: 500
  ASSERT_EQ(s.size(), 500u);
  const double chord = 2 * 0.5 * std::sin(0.004 / (2 * 0.5));
  for (std::size_t i = 0; i < s.size(); ++i) {
    EXPECT_NEAR((pt(s[i]) - Point(1, 2)).norm(), 0.5, 2e-7);
    if (i > 0) {
      EXPECT_NEAR((pt(s[i]) - pt(s[i - 1])).norm(), chord, 2e-7);
    }
  }
  EXPECT_EQ(s.back().x_mm, static_cast<float>(arc.end().x()));
  EXPECT_EQ(s.back().y_mm, static_cast<float>(arc.end().y()));
}

// Arc length between consecutive steps on an ellipse, recovered from the points themselves
// (their eccentric anomaly in the ellipse's frame), must be constant to 1e-6 relative.
void expect_uniform_ellipse(double rx, double ry, double rotation, double start, double sweep,
                            std::uint32_t steps) {
  const Element e = Element::ellipse({0.3, -0.2}, rx, ry, rotation, start, sweep);
  PathWalker w;
  w.start(e, steps);
  const double c = std::cos(rotation), s = std::sin(rotation);
  auto theta_of = [&](const Point& p, double near) {
    const Point d = p - Point(0.3, -0.2);
    const double x = c * d.x() + s * d.y(), y = -s * d.x() + c * d.y();
    double th = std::atan2(y / ry, x / rx);
    while (th - near > kPi) th -= 2 * kPi;  // unwrap next to the previous step
    while (th - near < -kPi) th += 2 * kPi;
    return th;
  };
  const double ds = e.length() / steps;
  double prev = start;
  double worst = 0;
  for (std::uint32_t j = 1; j <= steps; ++j) {
    const double th = theta_of(w.step(j), prev);
    const double len = ellipse_arc_length(rx, ry, std::min(prev, th), std::max(prev, th));
    worst = std::max(worst, std::abs(len - ds) / ds);
    prev = th;
  }
  EXPECT_LT(worst, 1e-6) << "rx " << rx << " ry " << ry << " sweep " << sweep;
  EXPECT_NEAR(prev, start + sweep, 1e-12);
}

TEST(Locus, EllipticalArcIsArcLengthUniform) {
  expect_uniform_ellipse(1.0, 0.6, 0.4, 0.2, 2 * kPi, 700);
  expect_uniform_ellipse(0.5, 0.1, -1.0, 1.0, -3.5, 400);  // flat, clockwise
  expect_uniform_ellipse(0.2, 2.0, 0.0, -2.0, 1.0, 50);    // few long steps
  expect_uniform_ellipse(3.0, 0.4, 2.0, 0.0, 4 * kPi, 3000);  // two turns
}

TEST(Locus, EllipseSamplesEndExactlyAndKeepSpeed) {
  const Element e = Element::ellipse({0, 0}, 1.0, 0.5, 0.3, 0.0, kPi);
  const double len = e.length();
  const auto s = run({Command::mark(e, 1000, CommandRole::stroke)});
  EXPECT_EQ(s.size(), static_cast<std::size_t>(std::llround(len / 0.01)));
  EXPECT_EQ(s.back().x_mm, static_cast<float>(e.end().x()));
  EXPECT_EQ(s.back().y_mm, static_cast<float>(e.end().y()));
}

TEST(Locus, DwellRepeatsThePointWithItsLaserBit) {
  const auto s = run({Command::mark(Element::line({0, 0}, {1, 0}), 1000, CommandRole::stroke),
                      Command::dwell({1, 0}, 7, true),
                      Command::dwell({1, 0}, 3, false)});
  ASSERT_EQ(s.size(), 110u);
  for (std::size_t i = 100; i < 107; ++i) {
    EXPECT_EQ(pt(s[i]), Point(1, 0));
    EXPECT_TRUE(s[i].laser);
  }
  for (std::size_t i = 107; i < 110; ++i) EXPECT_FALSE(s[i].laser);
}

// A job of 1000 random lines and arcs with lengths that are not whole ticks: every element ends
// exactly on its end point on the tick nearest its ideal end time; the samples' total path length
// equals the job's to under 1 µm, and the sample count is the ideal time rounded.
TEST(Locus, ThousandElementsAccumulateNoError) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> len(0.05, 0.9), ang(-kPi, kPi), speed(300, 3000);
  std::vector<Command> cmds;
  Point at(0, 0);
  double ideal_ticks = 0, total_len = 0;
  for (int i = 0; i < 1000; ++i) {
    const double v = speed(rng);
    const double a = ang(rng), l = len(rng);
    Element e = Element::line(at, at + l * Point(std::cos(a), std::sin(a)));
    if (i % 3 == 1) {  // an arc starting at `at`
      const double r = len(rng), a0 = ang(rng), sweep = (i % 2 ? 1.0 : -1.0) * len(rng) / r;
      e = Element::arc(at - r * Point(std::cos(a0), std::sin(a0)), r, a0, sweep);
    }
    cmds.push_back(Command::mark(e, v, CommandRole::stroke));
    ideal_ticks += e.length() / (v * kLocusTick);
    total_len += e.length();
    at = e.end();
  }
  const auto s = run(cmds, 333);
  EXPECT_EQ(s.size(), static_cast<std::size_t>(std::llround(ideal_ticks)));
  EXPECT_EQ(s.size(), LocusGenerator::count_samples(cmds, kLocusTick));

  // Each element's last sample is its end point; the steps inside it add up to its length.
  double ideal = 0, walked = 0;
  std::size_t prev_end = 0;
  Point prev_point(0, 0);
  for (const Command& c : cmds) {
    ideal += c.length_mm() / (c.speed_mm_s * kLocusTick);
    const std::size_t end = static_cast<std::size_t>(std::llround(ideal));
    ASSERT_GT(end, prev_end) << to_string(c.kind) << " len " << c.length_mm() << " v " << c.speed_mm_s;
    EXPECT_EQ(s[end - 1].x_mm, static_cast<float>(c.end().x()));
    EXPECT_EQ(s[end - 1].y_mm, static_cast<float>(c.end().y()));
    for (std::size_t k = prev_end; k < end; ++k) {
      const double chord = (pt(s[k]) - prev_point).norm();
      if (c.kind == CommandKind::arc) {
        const double r = std::get<CircularArc>(c.path.geometry()).radius;
        walked += 2 * r * std::asin(std::min(1.0, chord / (2 * r)));
      } else {
        walked += chord;
      }
      prev_point = pt(s[k]);
    }
    prev_end = end;
  }
  EXPECT_NEAR(walked, total_len, 1e-3);  // mm: 1 µm
}

TEST(Locus, BlockSizeDoesNotChangeTheStream) {
  std::vector<Command> cmds = {
      Command::jump({0, 0}, {1, 1}, 7000),
      Command::mark(Element::arc({1, 0}, 1, kPi / 2, -kPi), 900, CommandRole::stroke),
      Command::dwell({1, -1}, 5, true),
      Command::mark(Element::ellipse({1, -2}, 0.5, 1, 0, kPi / 2, kPi), 1300, CommandRole::stroke)};
  const auto a = run(cmds, 1);
  const auto b = run(cmds, 4096);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].x_mm, b[i].x_mm);
    EXPECT_EQ(a[i].y_mm, b[i].y_mm);
    EXPECT_EQ(a[i].laser, b[i].laser);
  }
}

TEST(Locus, TickIsConfigurable) {
  // 1 mm at 1000 mm/s: 100 samples at 10 µs, 50 at 20 µs.
  const std::vector<Command> c = {Command::mark(Element::line({0, 0}, {1, 0}), 1000, CommandRole::stroke)};
  EXPECT_EQ(run(c, 64, 20e-6).size(), 50u);
  EXPECT_EQ(run(c, 64, 10e-6).size(), 100u);
}

}  // namespace
}  // namespace mark
