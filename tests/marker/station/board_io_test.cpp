// Board I/O (issue 22): the trigger filter sample by sample (exact times), the option parsers,
// then the station in process on the emulated LMC board (JobSource on --device lmc-emulated with
// a real SQLite store): the test toggles the board's input pins and reads back the parts the
// store recorded and the output port words the board took.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "base/error.hpp"
#include "driver/lmc/codec.hpp"
#include "marker/cli/emulated_lmc_device.hpp"
#include "marker/cli/serve_board_io.hpp"
#include "tests/marker/station/served_station.hpp"

namespace mark {
namespace {

// --- TriggerFilter, with the times given ------------------------------------------------------

// Samples every 1 ms from `from_ms` to `to_ms` (exclusive) at `level`; the ms at which it fired.
std::vector<int> run(TriggerFilter& f, int from_ms, int to_ms, bool level) {
  std::vector<int> fired;
  for (int t = from_ms; t < to_ms; ++t)
    if (f.sample(level, t / 1000.0)) fired.push_back(t);
  return fired;
}

TEST(TriggerFilter, ACleanEdgeFiresOnceAfterTheLongerOfDebounceAndMinPulse) {
  TriggerFilter f(0.003, 0.008);
  EXPECT_TRUE(run(f, 0, 10, false).empty());
  EXPECT_EQ(run(f, 10, 100, true), std::vector<int>{18});  // rose at 10, held 8 ms
  EXPECT_TRUE(run(f, 100, 110, false).empty());
  EXPECT_EQ(run(f, 110, 200, true), std::vector<int>{118}) << "a new pulse after the fall";
  TriggerFilter g(0.008, 0.002);
  run(g, 0, 10, false);
  EXPECT_EQ(run(g, 10, 100, true), std::vector<int>{18}) << "debounce longer than the pulse";
}

TEST(TriggerFilter, APulseShorterThanTheMinimumFiresNothing) {
  TriggerFilter f(0.002, 0.020);
  run(f, 0, 10, false);
  EXPECT_TRUE(run(f, 10, 29, true).empty());  // 19 ms high: one short
  EXPECT_TRUE(run(f, 29, 60, false).empty());
  EXPECT_EQ(run(f, 60, 100, true), std::vector<int>{80});  // 20 ms: fires
}

TEST(TriggerFilter, ABounceTrainShorterThanTheDebounceIsOneEdge) {
  TriggerFilter f(0.010, 0.0);
  run(f, 0, 10, false);
  std::vector<int> fired;
  // Contacts bouncing: 2 ms high, 2 ms low, four times, then high for good.
  for (int i = 0; i < 4; ++i) {
    for (int t : run(f, 10 + 4 * i, 12 + 4 * i, true)) fired.push_back(t);
    for (int t : run(f, 12 + 4 * i, 14 + 4 * i, false)) fired.push_back(t);
  }
  for (int t : run(f, 26, 100, true)) fired.push_back(t);
  EXPECT_EQ(fired, std::vector<int>{36});  // 10 ms after the last rise
  // Release bounce (lows shorter than the debounce) does not end the pulse: no second mark.
  for (int i = 0; i < 4; ++i) {
    EXPECT_TRUE(run(f, 100 + 4 * i, 102 + 4 * i, false).empty());
    EXPECT_TRUE(run(f, 102 + 4 * i, 104 + 4 * i, true).empty());
  }
}

TEST(TriggerFilter, AnInputAlreadyHighAtStartIsNoEdge) {
  TriggerFilter f(0.0, 0.0);
  EXPECT_TRUE(run(f, 0, 50, true).empty());
  EXPECT_TRUE(run(f, 50, 51, false).empty());
  EXPECT_EQ(run(f, 51, 60, true), std::vector<int>{51}) << "zero debounce and pulse: the first high sample";
}

// --- the options ------------------------------------------------------------------------------

TEST(BoardIoOptions, TriggerAndSignalsParseOrSayWhatIsAllowed) {
  EXPECT_EQ(parse_board_trigger("lmc-input:0", "--trigger"), 0);
  EXPECT_EQ(parse_board_trigger("lmc-input:15", "--trigger"), 15);
  for (const char* bad : {"lmc-input:16", "lmc-input:", "lmc-input:-1", "lmc-input:1x", "input:3", "", "lmc-input:007"}) {
    try {
      parse_board_trigger(bad, "--trigger");
      ADD_FAILURE() << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("--trigger: ", 0), 0u) << e.what();
      EXPECT_NE(std::string(e.what()).find("15"), std::string::npos) << e.what();
    }
  }
  const BoardSignals s = parse_board_signals("busy=5,ready=4,error=7", "--signal");
  EXPECT_EQ(s.ready, 4);
  EXPECT_EQ(s.busy, 5);
  EXPECT_FALSE(s.done);
  EXPECT_EQ(s.error, 7);
  EXPECT_EQ(s.mask(), 0x00B0);
  EXPECT_EQ(s.word(StationLights{true, false, true, false}), 0x0010) << "done is not driven";
  const std::pair<const char*, const char*> bad[] = {
      {"ready=4,busy=4", "output bit 4 is given to two signals"},
      {"ready=4,ready=5", "ready is given twice"},
      {"ready=16", "0 to 15"},
      {"ready", "is not a signal"},
      {"go=3", "is not a signal"},
      {"ready=3,", "is not a signal"},
      {"", "empty"}};
  for (const auto& [text, why] : bad) {
    try {
      parse_board_signals(text, "--signal");
      ADD_FAILURE() << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << text << ": " << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("--signal: ", 0), 0u);
    }
  }
}

// --- the station on the emulated board --------------------------------------------------------

using Ms = std::chrono::milliseconds;
constexpr std::uint16_t kReady = 1u << 4, kBusy = 1u << 5, kDone = 1u << 6, kError = 1u << 7;

struct BoardStation {
  std::filesystem::path dir = test::fresh_store_dir("boardio");
  std::unique_ptr<cli::JobSource> source;
  std::unique_ptr<Station> station;
  std::unique_ptr<BoardIo> io;
  std::vector<std::string> log;
  std::mutex log_mutex;

  explicit BoardStation(bool virtual_time, double debounce_ms = 2, double min_pulse_ms = 2,
                        const std::string& signal = "ready=4,busy=5,done=6,error=7") {
    source = std::make_unique<cli::JobSource>(test::station_job_args(
        dir, "line.json", test::kStationJob, (dir / "line.serials.sqlite").string(), "lmc-emulated", virtual_time));
    station = std::make_unique<Station>(*source);
    cli::BoardIoArgs b{"lmc-input:3", signal, debounce_ms, min_pulse_ms};
    io = cli::open_board_io(*station, source->device(), *cli::parse_board_io(b), [this](const std::string& l) {
      std::lock_guard lock(log_mutex);
      log.push_back(l);
    });
  }
  ~BoardStation() {
    io.reset();
    station.reset();
    source.reset();
    std::filesystem::remove_all(dir);
  }
  lmc::EmulatedBoard& board() { return dynamic_cast<cli::EmulatedLmcDevice&>(source->device()).emulated_board(); }
  void pin(bool high) { board().set_inputs(high ? 0x0008 : 0x0000); }
  // Waits (≤ 20 s) until `n` parts ran and the station is not marking.
  bool parts(std::uint64_t n) {
    for (int i = 0; i < 20000; ++i) {
      const StationStatus s = station->status();
      if (s.parts >= n && s.state != StationState::marking) return s.parts == n;
      std::this_thread::sleep_for(Ms(1));
    }
    return false;
  }
  int logged(const std::string& prefix) {
    std::lock_guard lock(log_mutex);
    int n = 0;
    for (const auto& l : log) n += l.rfind(prefix, 0) == 0;
    return n;
  }
  std::uint16_t port() { return board().state().port; }
  // Until the poller has read the pin ten more times (≈ 10 ms): it has seen it as it is now
  // for longer than the tests' debounce (and a pin high at its first sample is no edge).
  void settle() {
    const std::size_t until = board().state().read_ports + 10;
    for (int i = 0; i < 2000 && board().state().read_ports < until; ++i) std::this_thread::sleep_for(Ms(1));
  }
  std::string log_text() {
    std::lock_guard lock(log_mutex);
    std::string t;
    for (const auto& l : log) t += l + "\n";
    return t + "parts " + std::to_string(station->status().parts) + ", state " +
           std::string(to_string(station->status().state));
  }
};

TEST(BoardIoStation, AnInputEdgeMarksExactlyOnePartAndTheOutputsFollow) {
  BoardStation s(true);
  // Ready at start (no part yet: not done).
  for (int i = 0; i < 1000 && s.port() != kReady; ++i) std::this_thread::sleep_for(Ms(1));
  EXPECT_EQ(s.port(), kReady);
  s.settle();
  const std::size_t before = s.board().port_writes().size();
  s.pin(true);
  ASSERT_TRUE(s.parts(1));
  std::this_thread::sleep_for(Ms(50));  // held high: still one part
  EXPECT_EQ(s.station->status().parts, 1u);
  ASSERT_TRUE(s.station->status().last);
  EXPECT_EQ(s.station->status().last->serials.at("serial"), 41);
  EXPECT_EQ(s.station->status().last->outcome, JobOutcome::done);
  s.pin(false);
  s.settle();
  s.pin(true);
  ASSERT_TRUE(s.parts(2)) << s.log_text();
  EXPECT_EQ(s.station->status().last->serials.at("serial"), 42) << "serial +1 per edge";
  EXPECT_EQ(s.io->triggers(), 2u);
  // Every port word the board took while the laser was enabled carried busy and nothing else
  // of the signals; the last one is ready + done, laser off.
  const auto words = s.board().port_writes();
  bool lasered = false;
  for (std::size_t i = before; i < words.size(); ++i)
    if (words[i].bits & 1) {
      lasered = true;
      EXPECT_EQ(words[i].bits & 0x00F0, kBusy) << i;
    }
  EXPECT_TRUE(lasered);
  for (int i = 0; i < 1000 && s.port() != (kReady | kDone); ++i) std::this_thread::sleep_for(Ms(1));
  EXPECT_EQ(s.port(), kReady | kDone);
  EXPECT_GT(s.board().state().read_ports, 10u);
}

TEST(BoardIoStation, APulseShorterThanTheMinimumMarksNothing) {
  BoardStation s(true, 1, 150);
  s.settle();
  s.pin(true);
  std::this_thread::sleep_for(Ms(10));
  s.pin(false);
  std::this_thread::sleep_for(Ms(300));
  EXPECT_EQ(s.station->status().parts, 0u);
  EXPECT_EQ(s.io->triggers(), 0u);
  s.pin(true);  // held: marks
  ASSERT_TRUE(s.parts(1));
}

TEST(BoardIoStation, ABounceTrainShorterThanTheDebounceMarksOnce) {
  BoardStation s(true, 40, 0);
  s.settle();
  for (int i = 0; i < 5; ++i) {  // ≈ 3 ms up, 3 ms down: each shorter than 40 ms
    s.pin(true);
    std::this_thread::sleep_for(Ms(3));
    s.pin(false);
    std::this_thread::sleep_for(Ms(3));
  }
  s.pin(true);
  ASSERT_TRUE(s.parts(1));
  std::this_thread::sleep_for(Ms(200));
  EXPECT_EQ(s.station->status().parts, 1u);
  EXPECT_EQ(s.io->triggers(), 1u);
}

TEST(BoardIoStation, AnEdgeWhileMarkingIsIgnoredAndLogged) {
  BoardStation s(false);  // real time: the part takes long enough to toggle the pin under it
  s.settle();
  ASSERT_FALSE(s.station->mark_async());
  ASSERT_EQ(s.station->status().state, StationState::marking);
  for (int i = 0; i < 1000 && (s.port() & 0x00F0) != kBusy; ++i) std::this_thread::sleep_for(Ms(1));
  EXPECT_EQ(s.port() & 0x00F0, kBusy) << "busy on the outputs while marking";
  s.pin(true);
  std::this_thread::sleep_for(Ms(60));
  const bool still_marking = s.station->status().state == StationState::marking;
  ASSERT_TRUE(s.parts(1));
  ASSERT_TRUE(still_marking) << "the part ended before the edge was seen: make it longer";
  EXPECT_EQ(s.logged("trigger ignored: busy"), 1);
  EXPECT_EQ(s.io->ignored(), 1u);
  std::this_thread::sleep_for(Ms(100));  // still high after the part: no edge, no part
  EXPECT_EQ(s.station->status().parts, 1u);
}

TEST(BoardIoStation, AFaultSetsTheErrorOutputWithTheLaserOff) {
  BoardStation s(true);
  s.settle();
  // The board never answers ExecuteList: the part fails, the station goes to error.
  s.board().set_single_fault({static_cast<std::uint16_t>(lmc::Op::ExecuteList), 1, lmc::SingleFault::Kind::no_answer});
  s.pin(true);
  for (int i = 0; i < 20000 && s.station->status().state != StationState::error; ++i)
    std::this_thread::sleep_for(Ms(1));
  ASSERT_EQ(s.station->status().state, StationState::error);
  for (int i = 0; i < 2000 && (s.port() & kError) == 0; ++i) std::this_thread::sleep_for(Ms(1));
  EXPECT_EQ(s.port(), kError) << "error alone; the laser bit clear";
  // A second edge in error: ignored.
  s.pin(false);
  s.settle();
  s.pin(true);
  for (int i = 0; i < 2000 && s.io->ignored() == 0; ++i) std::this_thread::sleep_for(Ms(1));
  EXPECT_EQ(s.logged("trigger ignored: error"), 1);
  ASSERT_FALSE(s.station->reset());
  for (int i = 0; i < 2000 && s.port() != kReady; ++i) std::this_thread::sleep_for(Ms(1));
  EXPECT_EQ(s.port(), kReady);
}

TEST(BoardIoStation, ASignalOnTheLaserBitOrAnotherDeviceIsRefused) {
  auto dir = test::fresh_store_dir("boardio-refuse");
  cli::MarkJobArgs a =
      test::station_job_args(dir, "line.json", test::kStationJob, (dir / "s.sqlite").string(), "lmc-emulated");
  {
    cli::JobSource source(a);
    Station station(source);
    try {
      cli::open_board_io(station, source.device(), *cli::parse_board_io({"", "ready=0", 5, 5}), {});
      ADD_FAILURE();
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("--signal: output bit 0 is the board's laser enable bit"), std::string::npos) << e.what();
    }
    try {
      cli::open_board_io(station, source.device(), *cli::parse_board_io({"", "busy=8", 5, 5}), {});
      ADD_FAILURE();
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("red pointer"), std::string::npos) << e.what();
    }
  }
  a.device = "sim";
  a.store.store = (dir / "t.sqlite").string();
  {
    cli::JobSource source(a);
    Station station(source);
    try {
      cli::open_board_io(station, source.device(), *cli::parse_board_io({"lmc-input:2", "", 5, 5}), {});
      ADD_FAILURE();
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("--trigger: the board's pins need --device lmc or lmc-emulated", 0), 0u) << e.what();
    }
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mark
