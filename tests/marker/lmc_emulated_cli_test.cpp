// The LMC path on the command line without a board: `mark --device lmc-emulated` (real and
// virtual time) reports the simulated scanner's figures through the board, close to the direct
// simulator's; `frame` and `lmc probe` run on it; laser sources and a .cor file's lens are
// refused where they do not fit, in one line naming both sides.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/marker/cli_runner.hpp"

namespace mark {
namespace {

nlohmann::json run_json(const std::vector<std::string>& args) {
  const auto r = test::run_cli(args);
  EXPECT_EQ(r.code, 0) << r.err;
  return r.code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
}

TEST(LmcEmulatedCli, MarkThroughTheEmulatedBoardReportsTheSimulatorsFigures) {
  const std::vector<std::string> job{"mark", "SN 0042", "--height", "2", "--speed", "400", "--json"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = job;
    a.insert(a.end(), extra.begin(), extra.end());
    return run_json(a);
  };
  const auto direct = with({"--virtual-time"});
  const auto board = with({"--device", "lmc-emulated"});
  const auto quick = with({"--device", "lmc-emulated:slowest", "--virtual-time"});
  for (const auto* j : {&board, &quick}) {
    ASSERT_EQ((*j)["outcome"], "done");
    ASSERT_TRUE(j->contains("quality"));
    const auto& q = (*j)["quality"];
    // The same strokes through the board: within the chords (5 µm) and a field unit of the
    // direct path, the whole text covered.
    EXPECT_LE(q["max_deviation_um"].get<double>(), direct["quality"]["max_deviation_um"].get<double>() + 5 + 2.4);
    EXPECT_GE(q["coverage_fraction"].get<double>(), 0.95);
    EXPECT_GT((*j)["device_figures"]["pulses"].get<double>(), 100);
    EXPECT_GT((*j)["device_figures"]["packets"].get<double>(), 0);
    EXPECT_FALSE(j->at("device_figures").contains("stop_confirmed"));  // nothing was stopped
  }
  EXPECT_NE(board["device"].get<std::string>().find("lmc-emulated:reference (lmc 4C4D4301, real time"), std::string::npos)
      << board["device"];
  EXPECT_NE(quick["device"].get<std::string>().find("virtual time"), std::string::npos);
  // The board took its own time, which the scanner saw tick for tick: the wall clock is never
  // shorter than the board's time (it is not a fast-forward model), and longer only by the host's
  // start and end (a few ms here; tens under a sanitizer on a loaded machine).
  const double board_s = board["device_figures"]["scanner_device_time_s"].get<double>();
  EXPECT_GE(board["mark_time_s"].get<double>(), board_s - 0.005);
  EXPECT_LE(board["mark_time_s"].get<double>(), board_s + 0.1);
}

TEST(LmcEmulatedCli, FrameAndProbeRunOnIt) {
  const auto frame = run_json({"frame", "SN 42", "--height", "2", "--device", "lmc-emulated:slowest", "--laps", "2",
                               "--json"});
  EXPECT_EQ(frame["laps"], 2);
  EXPECT_EQ(frame["orientation_mark"], true);
  const auto dir = test::fresh_temp_dir("lmc_emulated_cli_test");
  const std::string report = (dir / "probe.json").string();
  const auto probe = run_json({"lmc", "probe", "--device", "lmc-emulated:polygon_10us", "--json", "-o", report});
  EXPECT_EQ(probe["settings"]["polygon_delay_units"], "10us");
  EXPECT_EQ(probe["settings"]["word_ticks"], false);
  EXPECT_EQ(probe["polygon_delay"]["unit"], "10us");
  EXPECT_EQ(probe["serial"], "4C4D4301");
  EXPECT_EQ(probe["buffered_packets"], 4);
  std::ifstream in(report);
  EXPECT_EQ(nlohmann::json::parse(in), probe);  // the file holds the same report

  auto r = test::run_cli({"lmc", "probe", "--device", "lmc-capture:" + (dir / "x.lmc").string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("a capture file answers nothing; the probe needs a board that does"), std::string::npos) << r.err;
  r = test::run_cli({"lmc", "probe", "--device", "lmc-emulated:fast"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("no emulated board variant 'fast' (known: reference, exact_ticks"), std::string::npos) << r.err;
}

TEST(LmcEmulatedCli, SourcesTakeOnlyWhatTheyCan) {
  auto r = test::run_cli({"mark", "A", "--source", "co2", "--pulse-width", "100", "--device", "lmc-emulated"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--source co2: pulse width 100 ns: a co2 source (CO2 (continuous wave, PWM power)) has no "
                       "settable pulse width (only mopa: 2 .. 500 ns; 0 for the source's own)"),
            std::string::npos)
      << r.err;
  r = test::run_cli({"mark", "A", "--frequency", "500"});
  EXPECT_NE(r.err.find("--source fiber: frequency 500 kHz is outside what a fiber source runs (Q-switched fiber: 1 .. "
                       "200 kHz)"),
            std::string::npos)
      << r.err;
  for (const char* source : {"co2", "uv", "mopa"}) {
    const auto j = run_json({"mark", "A", "--height", "2", "--source", source, "--frequency", "20", "--power", "50",
                             "--device", "lmc-emulated", "--virtual-time", "--json"});
    EXPECT_EQ(j["outcome"], "done") << source;
    EXPECT_GT(j["device_figures"]["pulses"].get<double>(), 0) << source;
  }
}

TEST(LmcEmulatedCli, ThePensPowerIsCountedOnceInTheDose) {
  // The board's output carries the light's power (the pen's 20 % in its MarkCurrent): the
  // scanner must not scale it by the pen's power again, or every job below 100 % looks
  // under-dosed ("poor", 20 % of the pen's energy per mm). The share is the same at any power.
  double share[2] = {};
  for (int k = 0; k < 2; ++k) {
    const auto j = run_json({"mark", "SN 1", "--height", "2", "--power", k ? "100" : "20", "--device",
                             "lmc-emulated", "--virtual-time", "--json"});
    share[k] = j["quality"]["dose_per_mm_fraction"].get<double>();
  }
  EXPECT_GT(share[1], 0.8);
  EXPECT_NEAR(share[0], share[1], 0.01 * share[1]);
}

// The robust feed-forward pen of `cps --short` (SL10, the plant set's "high" row, 1410 mm/s),
// through the board as timed moves and directly on the simulator, on two plants.
// The robust feed-forward pen of `cps --short` (SL10, 1410 mm/s, look-ahead and feed-forward).
std::vector<std::string> robust_ff_pen() {
  return {"--head", "SL10", "--corner", "none", "--speed", "1410", "--jump-speed", "9600", "--tick", "10",
          "--laser-on-delay-us", "0", "--laser-off-delay-us", "0", "--lookahead", "--accel", "2200000",
          "--jump-accel", "18612000", "--curve-accel", "2200000", "--accel-limit", "44000000", "--junction-dv", "100",
          "--laser-switch-speed", "0", "--min-lit-speed", "141", "--ff-lag-us", "120", "--source", "fiber",
          "--frequency", "45"};
}

TEST(LmcEmulatedCli, FeedForwardRunsOnTheBoardAsTimedMoves) {
  const std::vector<std::string> pen = robust_ff_pen();
  for (const char* plant : {"", "dead_us=10"}) {
    auto on = [&](const char* device) {
      std::vector<std::string> a{"mark", "ABCDEFGHIJKLMNOPQRSTUVWXYZ", "--height", "1", "--align", "center",
                                 "--virtual-time", "--device", device, "--json"};
      a.insert(a.end(), pen.begin(), pen.end());
      if (*plant) a.insert(a.end(), {"--plant", plant});
      return run_json(a);
    };
    const auto direct = on("sim");
    const auto board = on("lmc-emulated");
    ASSERT_EQ(board["outcome"], "done") << plant;
    EXPECT_EQ(board["feed_forward"], true);
    EXPECT_EQ(direct["quality"]["class"], "high") << plant;
    EXPECT_EQ(board["quality"]["class"], "high") << plant << board["quality"];
    // The path: the direct one's, plus the cut's 2 µm and a 16-bit field unit (1.7 µm).
    EXPECT_LE(board["quality"]["max_deviation_um"].get<double>(),
              direct["quality"]["max_deviation_um"].get<double>() + 2 + 1.7)
        << plant;
    EXPECT_GE(board["quality"]["coverage_fraction"].get<double>(), 0.99) << plant;
    // The time: the locus's, tick for tick, plus the board's 8 ms opening of the oscillator.
    EXPECT_NEAR(board["device_figures"]["scanner_device_time_s"].get<double>(),
                direct["mark_time_s"].get<double>() + 0.008, 0.0005)
        << plant;
    // Many short moves: the speed changes along every stroke. The board never waited for them.
    EXPECT_GT(board["commands"].get<double>(), 20 * direct["commands"].get<double>()) << plant;
    EXPECT_EQ(board["device_figures"]["board_underrun_events"].get<double>(), 0) << plant;
  }
}

// A board that spends a tick on every word that is not a move (the emulated word_ticks variant):
// every timed move after a speed or power word starts a tick late, and the pre-compensated path
// falls behind its own timing. With --word-ticks (what `marker lmc probe` tells such a board's
// user to set) each move gives back the ticks the words before it took: the board's time is the
// reference board's to a few ticks and its path "high" again, within 3 µm of the reference
// board's (where a move is shorter than its words, at the corners, the rest is paid by the moves
// after it, and the path there lags by a tick: 13 capitals 5.19 against 2.58 µm, cps's 62
// characters 3.98 against 2.87).
TEST(LmcEmulatedCli, WordTicksGivesBackTheTicksABoardSpendsOnWords) {
  const std::vector<std::string> pen = robust_ff_pen();
  auto on = [&](const char* device, bool word_ticks) {
    std::vector<std::string> a{"mark", "ABCDEFGHIJKLM", "--height", "1", "--align", "center",
                               "--virtual-time", "--device", device, "--json"};
    a.insert(a.end(), pen.begin(), pen.end());
    if (word_ticks) a.push_back("--word-ticks");
    return run_json(a);
  };
  const auto reference = on("lmc-emulated", false);
  const auto unaware = on("lmc-emulated:word_ticks", false);
  const auto aware = on("lmc-emulated:word_ticks", true);
  ASSERT_EQ(reference["outcome"], "done");
  ASSERT_EQ(unaware["outcome"], "done");
  ASSERT_EQ(aware["outcome"], "done");
  const double reference_um = reference["quality"]["max_deviation_um"].get<double>();
  const double reference_s = reference["device_figures"]["scanner_device_time_s"].get<double>();
  EXPECT_EQ(reference["quality"]["class"], "high");
  // Unaware, the host's clock and the board's part by a tick a word: off the path, and late.
  EXPECT_NE(unaware["quality"]["class"], "high") << unaware["quality"];
  EXPECT_GT(unaware["quality"]["max_deviation_um"].get<double>(), reference_um + 5);
  EXPECT_GT(unaware["device_figures"]["scanner_device_time_s"].get<double>(), reference_s + 0.01);
  // Aware: "high", near the reference board's path, its time to 50 ticks (the words before the
  // first timed move and after the last are owed to no move).
  EXPECT_EQ(aware["quality"]["class"], "high") << aware["quality"];
  EXPECT_LE(aware["quality"]["max_deviation_um"].get<double>(), reference_um + 3);
  EXPECT_GE(aware["quality"]["coverage_fraction"].get<double>(), 0.99);
  EXPECT_NEAR(aware["device_figures"]["scanner_device_time_s"].get<double>(), reference_s, 0.0005);
  EXPECT_EQ(aware["device_figures"]["board_underrun_events"].get<double>(), 0);
}

// The input shaper on the board: the shaped locus goes to the board as timed moves like any
// other, so the emulated board's head with a 10 kHz mirror resonance marks the fast pen of
// docs/speed.md's "Input shaping" (5000 mm/s, 1.2e7 mm/s², 465 cps on the simulator) "high"
// shaped where unshaped it rings off the strokes (17.4 µm, dose per mm 61 %).
TEST(LmcEmulatedCli, TheInputShaperTakesOutTheResonanceOnTheBoardToo) {
  auto on = [&](bool shaped) {
    std::vector<std::string> a{"mark", "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789", "--height", "1",
                               "--align", "center", "--y", "0.5", "--virtual-time", "--device", "lmc-emulated",
                               "--head", "SL10", "--corner", "none", "--feed-forward", "--ff-lag-us", "120",
                               "--speed", "5000", "--accel", "1.2e7", "--curve-accel", "1.2e7", "--jump-accel",
                               "1.6e7", "--min-lit-speed", "500", "--source", "mopa", "--frequency", "250",
                               "--plant", "resonance_hz=10000", "--json"};
    if (shaped) a.insert(a.end(), {"--shaper-hz", "10000"});
    return run_json(a);
  };
  const auto plain = on(false);
  const auto shaped = on(true);
  ASSERT_EQ(plain["outcome"], "done");
  ASSERT_EQ(shaped["outcome"], "done");
  EXPECT_NE(plain["quality"]["class"], "high") << plain["quality"];
  EXPECT_GT(plain["quality"]["max_deviation_um"].get<double>(), 12);
  EXPECT_EQ(shaped["quality"]["class"], "high") << shaped["quality"];
  EXPECT_LT(shaped["quality"]["max_deviation_um"].get<double>(), 6);
  // Over 400 characters a second on the board's own clock (439: the board's words take time).
  EXPECT_LT(shaped["device_figures"]["scanner_device_time_s"].get<double>(), 62.0 / 400);
  EXPECT_EQ(shaped["device_figures"]["board_underrun_events"].get<double>(), 0);
}

// A correction table for a 70 mm lens, legacy format, every delta 0.
std::string cor_file_for(double lens_mm) {
  const auto path = test::fresh_temp_file("lmc_emulated_cli_test", "lens.cor");
  std::vector<char> b(0x24 + 4225 * 8, 0);
  const double scale = 65536.0 / lens_mm;
  std::memcpy(b.data() + 0x1C, &scale, 8);
  std::ofstream(path, std::ios::binary).write(b.data(), std::streamsize(b.size()));
  return path.string();
}

TEST(LmcEmulatedCli, ACorrectionFileForAnotherLensIsRefusedNamingBoth) {
  const std::string cor = cor_file_for(70);
  auto r = test::run_cli({"mark", "A", "--device", "lmc-emulated", "--cor", cor});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("lens.cor: made for a 70.000 mm lens (scale 936.2286 units/mm), but the lens field is 110 mm: "
                       "set the field to 70.000 mm or use a correction file for this lens"),
            std::string::npos)
      << r.err;
  const auto j = run_json({"mark", "A", "--height", "2", "--field", "70", "--device", "lmc-emulated", "--cor", cor,
                           "--virtual-time", "--json"});
  EXPECT_EQ(j["outcome"], "done");
  EXPECT_NEAR(j["device_figures"]["cor_lens_mm"].get<double>(), 70, 1e-9);
  EXPECT_EQ(j["device_figures"]["lens_mm"], 70);
}

}  // namespace
}  // namespace mark
