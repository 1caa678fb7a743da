// The pen options: cps prints its winning settings as `marker mark` options (pen_args_string);
// parsed back through the same options they give exactly the pen cps measured, for every
// strategy, whatever the head preset's defaults; mark runs them; bad values are refused by name.
#include "marker/cli/pen_options.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "base/error.hpp"
#include "marker/head/head_fit.hpp"
#include "marker/job/head_pen.hpp"
#include "tests/marker/cli_runner.hpp"

namespace mark {
namespace {

Pen parse(const std::string& options, const HeadModel& head) {
  cli::PenArgs args;
  CLI::App app;
  cli::add_pen_options(app, args);
  std::vector<std::string> argv;
  std::istringstream in(options);
  for (std::string w; in >> w;) argv.push_back(w);
  std::reverse(argv.begin(), argv.end());  // CLI11 takes them in reverse
  app.parse(argv);
  return cli::make_pen(args, head);
}

void expect_same(const Pen& a, const Pen& b) {
  auto near = [](double x, double y) { return std::abs(x - y) <= 1e-12 * std::max(1.0, std::abs(x)); };
  EXPECT_EQ(a.corner, b.corner);
  for (auto [x, y, what] : std::initializer_list<std::tuple<double, double, const char*>>{
           {a.mark_speed_mm_s, b.mark_speed_mm_s, "speed"}, {a.jump_speed_mm_s, b.jump_speed_mm_s, "jump"},
           {a.tick_s, b.tick_s, "tick"}, {a.laser_on_delay_s, b.laser_on_delay_s, "on"},
           {a.laser_off_delay_s, b.laser_off_delay_s, "off"}, {a.jump_delay_s, b.jump_delay_s, "jd"},
           {a.jump_settle_mm, b.jump_settle_mm, "js"}, {a.mark_delay_s, b.mark_delay_s, "md"},
           {a.polygon_delay_s, b.polygon_delay_s, "pd"}, {a.blank_angle_deg, b.blank_angle_deg, "ba"},
           {a.run_in_mm.value_or(-1), b.run_in_mm.value_or(-1), "ri"}, {a.min_run_in_mm, b.min_run_in_mm, "mri"},
           {a.run_out_mm, b.run_out_mm, "ro"}, {a.settle_mm, b.settle_mm, "settle"},
           {a.join_speed_mm_s, b.join_speed_mm_s, "join"}, {a.tracking_error_s, b.tracking_error_s, "tau"},
           {a.accel_mm_s2, b.accel_mm_s2, "acc"}, {a.jump_accel_mm_s2, b.jump_accel_mm_s2, "jacc"},
           {a.curve_accel_mm_s2, b.curve_accel_mm_s2, "cacc"}, {a.accel_limit_mm_s2, b.accel_limit_mm_s2, "lim"},
           {a.junction_dv_mm_s, b.junction_dv_mm_s, "dv"}, {a.laser_switch_speed_mm_s, b.laser_switch_speed_mm_s, "sw"},
           {a.min_lit_speed_mm_s, b.min_lit_speed_mm_s, "minlit"}, {a.ff_lag_s, b.ff_lag_s, "lag"},
           {a.ff_inertia_s2, b.ff_inertia_s2, "inertia"}, {a.shaper_hz, b.shaper_hz, "shaper"},
           {a.shaper_zeta, b.shaper_zeta, "shaper zeta"}})
    EXPECT_TRUE(near(x, y)) << what << ": " << x << " vs " << y;
  EXPECT_EQ(a.lookahead || a.feed_forward(), b.lookahead || b.feed_forward());
  EXPECT_EQ(a.shaper, b.shaper);
}

TEST(PenOptions, PrintedOptionsReproduceThePenOnAnyHead) {
  SimScannerOptions o;
  o.head = head_sa14();
  const HeadProfile sa14 = identify_head(o).with_lag_error(0.1);
  for (CornerStrategy corner : {CornerStrategy::blanking, CornerStrategy::delays, CornerStrategy::none})
    for (int mode = 0; mode < 3; ++mode) {
      PenRules r;
      r.lookahead = mode >= 1;
      r.feed_forward = mode == 2;
      r.accel_share = 0.37;
      r.min_run_in = 1.7;
      r.polygon = 0.3;
      Pen pen = pen_for_profile(sa14, corner, 1234.5, 10e-6, r);
      if (r.lookahead) {  // and a shaper, which only the look-ahead planner reads
        pen.shaper_hz = 8765;
        pen.shaper_zeta = 0.035;
        pen.shaper = ShaperKind::zvd;
      }
      // Parsed against another head (one fast enough for SA14's jumps): every parameter is
      // explicit, no default leaks in.
      expect_same(pen, parse(cli::pen_args_string(pen), head_sl10()));
    }
}

TEST(PenOptions, BadValuesAreRefusedByName) {
  auto error = [](const std::string& options) {
    try {
      parse(options, head_sl10());
    } catch (const std::exception& e) {  // InputError, or CLI11's range check while parsing
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error("--accel -5").find("--accel: -5 is outside the range 0 to 1e+10 mm/s²"), std::string::npos)
      << error("--accel -5");
  // Within the option's range but beyond the head's.
  EXPECT_EQ(error("--jump-speed 50000"),
            "--jump-speed: 50000 is outside the range 1 to 19200 mm/s (head SL10's positioning limit)");
  EXPECT_NE(error("--corner wavy").find("'wavy' is not one of blanking, delays, none"), std::string::npos);
  EXPECT_NE(error("--speed 0").find("--speed: 0 is outside the range"), std::string::npos);
  EXPECT_NE(error("--head-profile /nonexistent.json").find("/nonexistent.json: cannot read the head profile: No such file or directory"), std::string::npos);
  // A profile identified on another head is refused, naming both.
  const auto sa14 = test::fresh_temp_file("pen_options_test", "sa14.json");
  ASSERT_EQ(test::run_cli({"head", "identify", "--head", "SA14", "-o", sa14.string()}).code, 0);
  EXPECT_NE(error("--head-profile " + sa14.string()).find("identified on head SA14, but the head is SL10"),
            std::string::npos)
      << error("--head-profile " + sa14.string());
  // A zero feed-forward model given by hand compensates nothing: the pen stays without it.
  EXPECT_FALSE(parse("--ff-lag-us 0 --ff-inertia-us2 0", head_sl10()).feed_forward());
}

TEST(PenOptions, MarkRunsTheFeedForwardPenOnTheSimulatedHead) {
  const auto profile = test::fresh_temp_file("pen_options_test", "sl10.json");
  ASSERT_EQ(test::run_cli({"head", "identify", "--head", "SL10", "-o", profile.string()}).code, 0);
  const test::CliResult r = test::run_cli(
      {"mark", "Speed 1", "--height", "1", "--head", "SL10", "--head-profile", profile.string(),
       "--corner", "none", "--feed-forward", "--speed", "3000", "--frequency", "150", "--virtual-time", "--json"});
  // 150 kHz: pulses 20 µm apart at 3000 mm/s on the 40 µm spot (the default 30 kHz leaves
  // 60 µm gaps between spots, and the class says "poor").
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["feed_forward"], true);
  EXPECT_EQ(j["head_model"], "first");
  EXPECT_EQ(j["quality"]["class"], "high") << r.out;
  // The same text without feed-forward at that speed: the lag shows.
  const test::CliResult lag = test::run_cli({"mark", "Speed 1", "--height", "1", "--corner", "none",
                                             "--speed", "3000", "--virtual-time", "--json"});
  ASSERT_EQ(lag.code, 0) << lag.err;
  EXPECT_EQ(nlohmann::json::parse(lag.out)["quality"]["class"], "poor");
  // A second-order head and a slow laser, as cps's rows.
  const test::CliResult second = test::run_cli(
      {"mark", "Speed 1", "--height", "1", "--head-model", "second", "--laser-rise-us", "20",
       "--virtual-time", "--json"});
  ASSERT_EQ(second.code, 0) << second.err;
  EXPECT_EQ(nlohmann::json::parse(second.out)["head_model"], "second");
  EXPECT_EQ(nlohmann::json::parse(second.out)["laser_rise_us"], 20);
}

}  // namespace
}  // namespace mark
