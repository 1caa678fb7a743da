// Line memory throughput, producer thread → consumer thread (target ≥ 50 M samples/s), for
// block pushes of the sizes a locus generator would use, single-sample pushes (direct, and
// through the batching LineWriter), and the drain in virtual time feeding a sink that only counts.
#include <benchmark/benchmark.h>

#include <thread>
#include <vector>

#include "ringbuffer/backoff.hpp"
#include "ringbuffer/drain.hpp"
#include "ringbuffer/line_memory.hpp"
#include "ringbuffer/line_writer.hpp"
#include "ringbuffer/scan_sample.hpp"

namespace mark {
namespace {

constexpr std::size_t samples_per_run = 1 << 22;  // 4 M samples per iteration

// Producer pushes `chunk` samples at a time (1 = push(const T&)); consumer pops 1024 at a time.
void BM_ProducerConsumer(benchmark::State& state) {
  const auto chunk = static_cast<std::size_t>(state.range(0));
  const auto capacity = static_cast<std::size_t>(state.range(1));
  std::vector<ScanSample> src(chunk);
  for (std::size_t i = 0; i < chunk; ++i) src[i] = {static_cast<float>(i), 1.0f, true, 255};
  std::vector<ScanSample> dst(1024);
  for (auto _ : state) {
    LineMemory<ScanSample> memory(capacity);
    std::thread producer([&] {
      for (std::size_t sent = 0; sent < samples_per_run; sent += chunk) {
        if (chunk == 1)
          memory.push(src[0]);
        else
          memory.push(std::span<const ScanSample>(src));
      }
      memory.close();
    });
    std::size_t got = 0;
    float check = 0;
    Backoff backoff;  // as the drain does: don't starve the producer of a core while empty
    for (;;) {
      const bool closed = memory.closed();
      const std::size_t n = memory.pop(std::span<ScanSample>(dst));
      got += n;
      if (n) {
        check += dst[n - 1].x_mm;
        backoff.reset();
      } else if (closed) {
        break;
      } else {
        backoff.pause();
      }
    }
    producer.join();
    benchmark::DoNotOptimize(check);
    if (got != samples_per_run) state.SkipWithError("samples lost");
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * samples_per_run));
}
BENCHMARK(BM_ProducerConsumer)
    ->ArgNames({"chunk", "capacity"})
    ->Args({1, 1 << 16})
    ->Args({64, 1 << 16})
    ->Args({256, 1 << 16})
    ->Args({1024, 1 << 16})
    ->Args({256, 1 << 12})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// One sample at a time through the batching LineWriter (how a locus generator that emits
// single samples should feed the memory).
void BM_LineWriterSingleSamples(benchmark::State& state) {
  const auto batch = static_cast<std::size_t>(state.range(0));
  std::vector<ScanSample> dst(1024);
  for (auto _ : state) {
    LineMemory<ScanSample> memory(1 << 16);
    std::thread producer([&] {
      LineWriter<ScanSample> writer(memory, batch);
      for (std::size_t i = 0; i < samples_per_run; ++i)
        writer.push(ScanSample{static_cast<float>(i), 1.0f, true, 255});
      writer.close();
    });
    std::size_t got = 0;
    Backoff backoff;
    for (;;) {
      const bool closed = memory.closed();
      const std::size_t n = memory.pop(std::span<ScanSample>(dst));
      got += n;
      if (n) {
        backoff.reset();
      } else if (closed) {
        break;
      } else {
        backoff.pause();
      }
    }
    producer.join();
    if (got != samples_per_run) state.SkipWithError("samples lost");
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * samples_per_run));
}
BENCHMARK(BM_LineWriterSingleSamples)->ArgName("batch")->Arg(64)->Arg(256)->UseRealTime()->Unit(benchmark::kMillisecond);

class CountingSink : public Sink<ScanSample> {
 public:
  void write(std::span<const ScanSample> block) override {
    count += block.size();
    last = block.back().x_mm;
  }
  void halt() noexcept override {}
  std::size_t count = 0;
  float last = 0;
};

// The whole readout path in virtual time: producer → line memory → drain thread → sink.
void BM_DrainVirtualTime(benchmark::State& state) {
  const auto block = static_cast<std::size_t>(state.range(0));
  std::vector<ScanSample> src(256, ScanSample{1, 2, true, 255});
  for (auto _ : state) {
    LineMemory<ScanSample> memory(1 << 16);
    CountingSink sink;
    Drain<ScanSample> drain(memory, sink, {.block_samples = block, .virtual_time = true});
    drain.start();
    for (std::size_t sent = 0; sent < samples_per_run; sent += src.size())
      memory.push(std::span<const ScanSample>(src));
    memory.close();
    drain.join();
    if (sink.count != samples_per_run) state.SkipWithError("samples lost");
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * samples_per_run));
}
BENCHMARK(BM_DrainVirtualTime)->ArgName("block")->Arg(100)->Arg(1000)->UseRealTime()->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace mark
