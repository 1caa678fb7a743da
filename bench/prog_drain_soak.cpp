// drain_soak: the line memory read out in real time at 100 kHz for N seconds (default 60) while
// a producer writes into it alongside, into the simulated scanner (or a null sink). Prints the
// underruns (target 0), the block lateness (median, p99, max) and the peak fill. Exit status 1
// if any underrun occurred. --hog N runs N busy threads beside it (a CPU-hogging neighbour);
// --no-realtime leaves the drain at normal priority, so the two can be compared in one run.
//
//   drain_soak [--seconds 60] [--rate 100000] [--block 100] [--capacity 65536] [--sink sim|null]
//              [--hog N] [--no-realtime]
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "driver/sim/sim_scanner.hpp"
#include "ringbuffer/drain.hpp"
#include "ringbuffer/line_memory.hpp"

namespace {

class NullSink : public mark::Sink<mark::ScanSample> {
 public:
  void write(std::span<const mark::ScanSample>) override {}
  void halt() noexcept override {}
};

// A producer shaped like a locus generator: a 20 mm circle at 1 m/s, lit, in chunks of 256
// samples, pushed as fast as the memory takes them.
void produce(mark::LineMemory<mark::ScanSample>& memory, std::uint64_t total, double rate_hz) {
  const double r = 10, step_rad = (1000.0 / rate_hz) / r;
  std::vector<mark::ScanSample> chunk(256);
  std::uint64_t k = 0;
  while (k < total) {
    const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(chunk.size(), total - k));
    for (std::size_t i = 0; i < n; ++i, ++k) {
      const double a = static_cast<double>(k) * step_rad;
      chunk[i] = {static_cast<float>(r * std::cos(a)), static_cast<float>(r * std::sin(a)), true, 255};
    }
    if (!memory.push(std::span<const mark::ScanSample>(chunk.data(), n))) return;
  }
  memory.close();
}

}  // namespace

int main(int argc, char** argv) {
  double seconds = 60, rate = 100000;
  std::size_t block = 100, capacity = 1 << 16;
  std::string sink_name = "sim";
  int hogs = 0;
  bool realtime = true;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* name) -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "drain_soak: %s needs a value\n", name);
        std::exit(2);
      }
      return argv[++i];
    };
    try {
      if (a == "--seconds") seconds = std::stod(value("--seconds"));
      else if (a == "--rate") rate = std::stod(value("--rate"));
      else if (a == "--block") block = std::stoul(value("--block"));
      else if (a == "--capacity") capacity = std::stoul(value("--capacity"));
      else if (a == "--sink") sink_name = value("--sink");
      else if (a == "--hog") hogs = std::stoi(value("--hog"));
      else if (a == "--no-realtime") realtime = false;
      else {
        std::fprintf(stderr, "drain_soak: unknown option %s\n", a.c_str());
        return 2;
      }
    } catch (const std::exception&) {
      std::fprintf(stderr, "drain_soak: bad value for %s\n", a.c_str());
      return 2;
    }
  }
  if (!(seconds > 0) || !(rate > 0) || block == 0 || capacity == 0 ||
      (sink_name != "sim" && sink_name != "null") || hogs < 0 || hogs > 64) {
    std::fprintf(stderr, "drain_soak: need --seconds > 0, --rate > 0, --block ≥ 1, --capacity ≥ 1, --sink sim|null, --hog 0..64\n");
    return 2;
  }

  const auto total = static_cast<std::uint64_t>(std::llround(seconds * rate));
  mark::LineMemory<mark::ScanSample> memory(capacity);
  mark::SimScannerOptions sim_options;
  sim_options.tick_s = 1 / rate;
  sim_options.record_lit_paths = false;
  mark::SimScanner sim(sim_options);
  NullSink null_sink;
  mark::Sink<mark::ScanSample>& sink =
      sink_name == "sim" ? static_cast<mark::Sink<mark::ScanSample>&>(sim) : null_sink;

  mark::Drain<mark::ScanSample> drain(
      memory, sink,
      {.rate_hz = rate, .block_samples = block, .start_fill = capacity / 2,
       .realtime_priority = realtime ? 80 : 0});
  std::printf("drain_soak: %.0f s at %.0f Hz, %zu-sample blocks, capacity %zu, sink %s, %d hog "
              "thread(s), realtime %s\n",
              seconds, rate, block, capacity, sink_name.c_str(), hogs, realtime ? "asked" : "off");
  std::atomic<bool> stop_hogs{false};
  std::vector<std::thread> hog_threads;
  for (int h = 0; h < hogs; ++h)
    hog_threads.emplace_back([&stop_hogs] {
      volatile double x = 1;
      while (!stop_hogs.load(std::memory_order_relaxed)) x = x * 1.0000001 + 1e-9;
    });
  std::fflush(stdout);
  const auto t0 = std::chrono::steady_clock::now();
  drain.start();
  std::thread producer(produce, std::ref(memory), total, rate);
  mark::DrainStats st;
  try {
    st = drain.join();
  } catch (const std::exception& e) {
    producer.join();
    stop_hogs = true;
    for (std::thread& t : hog_threads) t.join();
    std::fprintf(stderr, "drain_soak: %s\n", e.what());
    return 1;
  }
  producer.join();
  stop_hogs = true;
  for (std::thread& t : hog_threads) t.join();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  std::printf("samples out        %llu (device time %.3f s, wall %.3f s)\n",
              static_cast<unsigned long long>(st.samples_out), st.samples_out / rate, wall);
  std::printf("underruns          %llu events, %llu samples\n",
              static_cast<unsigned long long>(st.underrun_events),
              static_cast<unsigned long long>(st.underrun_samples));
  std::printf("block lateness     median %.1f us, p99 %.1f us, max %.1f us\n", st.lateness_median_us,
              st.lateness_p99_us, st.lateness_max_us);
  std::printf("peak fill          %zu of %zu samples\n", st.peak_fill, capacity);
  std::printf("sched_fifo         %s\n", st.realtime_granted ? "granted" : "not granted");
  if (sink_name == "sim") std::printf("sim device time    %.3f s\n", sim.device_time_s());
  // The job's samples and the drain's closing safe sample.
  return st.end == mark::DrainEnd::completed && st.samples_out == total + 1 ? 0 : 1;
}
