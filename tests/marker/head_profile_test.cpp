// Head profiles: the JSON file round-trips, every bad value is refused with the key and its range,
// and `marker head identify` writes a profile that loads back to the identified numbers.
#include "marker/head/head_profile.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "marker/job/head_pen.hpp"
#include "tests/marker/cli_runner.hpp"

namespace mark {
namespace {

HeadProfile sample_profile() {
  HeadProfile p = datasheet_profile(head_sa14());
  p.source = "identified";
  p.fit_rms_first_um = 0.8;
  p.fit_rms_second_um = 1e-4;
  return p;
}

std::string profile_error_of(const std::string& json) {
  try {
    parse_head_profile(json, "p.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(HeadProfile, JsonRoundTrip) {
  const HeadProfile p = sample_profile();
  const HeadProfile q = parse_head_profile(head_profile_json(p), "mem");
  EXPECT_EQ(q.head, "SA14");
  EXPECT_EQ(q.model, ServoOrder::second);
  EXPECT_DOUBLE_EQ(q.tau_s, p.tau_s);
  EXPECT_DOUBLE_EQ(q.omega_n_rad_s, p.omega_n_rad_s);
  EXPECT_DOUBLE_EQ(q.zeta, p.zeta);
  EXPECT_DOUBLE_EQ(q.max_speed_mm_s, 32000);
  EXPECT_DOUBLE_EQ(q.max_accel_mm_s2, 5.12e7);
  EXPECT_DOUBLE_EQ(q.field_mm, 110);
  EXPECT_DOUBLE_EQ(q.fit_rms_second_um, 1e-4);
  EXPECT_EQ(q.source, "identified");
  // Keys name their units.
  const auto j = nlohmann::json::parse(head_profile_json(p));
  for (const char* key : {"tau_s", "omega_n_rad_s", "zeta", "max_speed_mm_s", "max_accel_mm_s2",
                          "field_mm", "tick_s"})
    EXPECT_TRUE(j.contains(key)) << key;
  // No resonance seen: no key; one seen: both, back as they were.
  EXPECT_FALSE(j.contains("resonance_hz"));
  EXPECT_EQ(q.resonance_hz, 0);
  HeadProfile r = p;
  r.resonance_hz = 9950;
  r.resonance_zeta = 0.035;
  const HeadProfile s = parse_head_profile(head_profile_json(r), "mem");
  EXPECT_DOUBLE_EQ(s.resonance_hz, 9950);
  EXPECT_DOUBLE_EQ(s.resonance_zeta, 0.035);
}

// A profile with a resonance shapes every look-ahead pen planned with it, where the tick can;
// a pen without look-ahead, or a resonance above a quarter of the tick rate, is not shaped.
TEST(HeadProfile, AResonanceInTheProfileShapesLookAheadPens) {
  HeadProfile p = datasheet_profile(head_sl10());
  p.resonance_hz = 9950;
  p.resonance_zeta = 0.03;
  PenRules planned;
  planned.lookahead = true;
  const Pen shaped = pen_for_profile(p, CornerStrategy::none, 2000, 10e-6, planned);
  EXPECT_DOUBLE_EQ(shaped.shaper_hz, 9950);
  EXPECT_DOUBLE_EQ(shaped.shaper_zeta, 0.03);
  EXPECT_EQ(pen_for_profile(p, CornerStrategy::blanking, 2000, 10e-6, PenRules{}).shaper_hz, 0);
  p.resonance_hz = 30000;
  EXPECT_EQ(pen_for_profile(p, CornerStrategy::none, 2000, 10e-6, planned).shaper_hz, 0);
}

TEST(HeadProfile, LagAndInverseFilterTermsOfEachModel) {
  HeadProfile p = sample_profile();
  EXPECT_DOUBLE_EQ(p.lag_s(), 2 * 0.7 / p.omega_n_rad_s);
  EXPECT_DOUBLE_EQ(p.inertia_s2(), 1 / (p.omega_n_rad_s * p.omega_n_rad_s));
  p.model = ServoOrder::first;
  EXPECT_DOUBLE_EQ(p.lag_s(), 0.21e-3);
  EXPECT_DOUBLE_EQ(p.inertia_s2(), 0.0);
  // A model error scales the ramp lag of either model by the same share.
  EXPECT_NEAR(p.with_lag_error(0.1).lag_s(), 1.1 * p.lag_s(), 1e-15);
  p.model = ServoOrder::second;
  EXPECT_NEAR(p.with_lag_error(-0.1).lag_s(), 0.9 * p.lag_s(), 1e-15);
}

TEST(HeadProfile, BadFilesAreRefusedNamingKeyAndRange) {
  auto j = nlohmann::json::parse(head_profile_json(sample_profile()));
  EXPECT_NE(profile_error_of("{").find("p.json: not JSON"), std::string::npos);
  EXPECT_NE(profile_error_of("[1,2]").find("one JSON object"), std::string::npos);
  EXPECT_NE(profile_error_of("{\"tau_s\": 1e400}").find("not JSON"), std::string::npos);  // found by fuzzing
  auto with = [&](const char* key, nlohmann::json value) {
    auto k = j;
    k[key] = value;
    return profile_error_of(k.dump());
  };
  EXPECT_NE(with("format", "other").find("'format'"), std::string::npos);
  EXPECT_NE(with("version", 2).find("'version' must be 1"), std::string::npos);
  EXPECT_NE(with("model", "third").find("'model'"), std::string::npos);
  EXPECT_NE(with("zeta", -1).find("'zeta' is -1, outside 0.001 to 100"), std::string::npos);
  EXPECT_NE(with("max_accel_mm_s2", "fast").find("'max_accel_mm_s2' must be a number"),
            std::string::npos);
  EXPECT_NE(with("max_speed_mm_s", 1e300).find("'max_speed_mm_s'"), std::string::npos);
  EXPECT_NE(with("tau_s", 0.12).find("'tau_s' is 0.12"), std::string::npos);  // ms given as s
  EXPECT_NE(with("resonance_hz", 50).find("'resonance_hz' is 50, outside 100 to 250000"), std::string::npos);
  EXPECT_NE(with("resonance_zeta", 0.9).find("'resonance_zeta' is 0.9, outside 0 to 0.5"), std::string::npos);
  auto k = j;
  k.erase("omega_n_rad_s");  // the chosen (second-order) model's parameter
  EXPECT_NE(profile_error_of(k.dump()).find("'omega_n_rad_s' is missing"), std::string::npos);
  k = j;
  k["model"] = "first";
  k.erase("omega_n_rad_s");  // not needed by a first-order profile
  EXPECT_EQ(profile_error_of(k.dump()), "");
}

TEST(HeadProfile, SaveWritesTheWholeFileAndLoadReadsIt) {
  const auto path = test::fresh_temp_file("head_profile_test", "p.json");
  save_head_profile(sample_profile(), path.string());
  EXPECT_FALSE(std::filesystem::exists(path.string() + ".part"));
  EXPECT_DOUBLE_EQ(load_head_profile(path.string()).zeta, 0.7);
  EXPECT_THROW(load_head_profile((path.parent_path() / "missing.json").string()), InputError);
}

TEST(HeadCli, IdentifyWritesAProfileOfTheSimulatedHead) {
  const auto path = test::fresh_temp_file("head_cli_test", "sa14.json");
  const test::CliResult r = test::run_cli({"head", "identify", "--head", "SA14", "-o", path.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("model: second order"), std::string::npos) << r.out;
  const HeadProfile p = load_head_profile(path.string());
  EXPECT_EQ(p.model, ServoOrder::second);
  EXPECT_NEAR(p.zeta, 0.7, 0.014);
  EXPECT_NEAR(p.max_accel_mm_s2, 5.12e7, 0.02 * 5.12e7);

  // A first-order variant of it, as JSON on stdout.
  const test::CliResult j = test::run_cli(
      {"head", "identify", "--head", "SA14", "--head-model", "first", "-o", path.string(), "--json"});
  ASSERT_EQ(j.code, 0) << j.err;
  EXPECT_EQ(parse_head_profile(j.out, "stdout").model, ServoOrder::first);

  const test::CliResult bad = test::run_cli({"head", "identify", "--head", "SL99"});
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("--head 'SL99' is not one of SL10, SL14, cheap, SA14"), std::string::npos);
  const test::CliResult zeta =
      test::run_cli({"head", "identify", "--head-model", "second", "--head-zeta", "50"});
  EXPECT_EQ(zeta.code, 1);
  EXPECT_NE(zeta.err.find("--head-zeta: 50 is outside the range 0.05 to 10"), std::string::npos) << zeta.err;
}

}  // namespace
}  // namespace mark
