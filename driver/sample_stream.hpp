#pragma once
// The one streaming core of every sample-level job — the laser job's locus and the gravure
// stylus's filtered toolpath alike: begin_job, a producer fills the line memory on the calling
// thread while the fixed-rate drain reads it out to the device on its own thread, end_job, and
// the ending classified (driver/stream_ending.hpp).
//
//   producer ─► LineMemory<T> ─► Drain<T> (fixed rate, filter, safe samples) ─► SampleDevice<T>
//
// Every buffer the drain thread touches is sized here before the drain starts, so the drain
// thread never allocates (tests/alloc); in real time the process's pages are then locked if
// asked. A producer that throws stops the drain (the device gets its safe sample and is halted)
// and the device's job is ended before the error goes on. Stop requests, injected stops and
// underruns are the drain's (DrainOptions); their latency and the stop point are in the result.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <exception>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

#include "driver/device.hpp"
#include "driver/stream_ending.hpp"
#include "ringbuffer/drain.hpp"
#include "ringbuffer/line_memory.hpp"
#include "ringbuffer/realtime.hpp"

namespace mark {

template <class T>
struct StreamOptions {
  DrainOptions drain;                     // rate, block, virtual time, start fill, stop, injection
  SampleFilter<T>* filter = nullptr;      // on the drain thread (the laser delay line); not owned
  std::size_t memory_samples = 1u << 16;  // line memory capacity
  std::size_t first_block = 4096;         // the producer's first write (small: the drain starts early)
  std::size_t block = 4096;               // its later writes
  bool lock_memory = false;               // lock the process's pages once everything is sized
  std::string_view safe_state = "laser off";  // what the safe sample means, for messages
  // Called on the producer's thread about every 100 ms with samples out and `total_samples`,
  // and until the drain has put out `total_samples` once the producer is done.
  std::function<void(std::uint64_t done, std::uint64_t total)> progress;
  std::uint64_t total_samples = 0;
};

struct StreamResult {
  DeviceReport device;            // end_job's report
  DrainStats drain;               // how the drain ended, its figures
  StreamEnding ending;            // done / aborted / failed, the fault, where it stopped
  std::uint64_t produced = 0;     // samples the producer generated
  double first_block_s = 0;       // wall time from the producer's start to its first block stored
  bool memory_locked = false;
};

// Streams one job to `device`: begin_job(header), then `produce(out)` — which fills up to
// out.size() samples and returns how many, 0 at the end — until it is done or the drain stops.
// Throws what begin_job throws (the device untouched otherwise) and what the producer throws
// (after the device's job has ended, laser off).
template <HasSafeSample T, class Producer>
StreamResult stream_samples(SampleDevice<T>& device, const JobHeader& header, Producer&& produce,
                            const StreamOptions<T>& options) {
  using Clock = std::chrono::steady_clock;
  StreamResult result;
  device.begin_job(header);

  LineMemory<T> memory(std::max<std::size_t>(options.memory_samples, 1));
  Drain<T> drain(memory, device, options.drain, options.filter);
  const std::size_t first = std::max<std::size_t>(options.first_block, 1);
  const std::size_t later = std::max<std::size_t>(options.block, 1);
  std::vector<T> buffer(std::max(first, later));
  if (options.lock_memory) result.memory_locked = lock_memory();
  drain.start();

  std::exception_ptr failure;
  try {
    const Clock::time_point start = Clock::now();
    Clock::time_point last_report = start;
    bool first_stored = false;
    while (const std::size_t n = produce(std::span<T>(buffer.data(), first_stored ? later : first))) {
      result.produced += n;
      if (!memory.push(std::span<const T>(buffer.data(), n))) break;  // the drain stopped
      if (!first_stored) {
        result.first_block_s = std::chrono::duration<double>(Clock::now() - start).count();
        first_stored = true;
      }
      if (options.progress && Clock::now() - last_report > std::chrono::milliseconds(100)) {
        options.progress(drain.samples_out(), options.total_samples);
        last_report = Clock::now();
      }
    }
    memory.close();
    if (options.progress) {
      while (!memory.aborted() && drain.samples_out() < options.total_samples) {
        options.progress(drain.samples_out(), options.total_samples);
        if (drain.finished_within(std::chrono::milliseconds(100))) break;
      }
    }
  } catch (...) {
    // The producer failed: stop the drain (the device gets its safe sample) before reporting.
    failure = std::current_exception();
    drain.abort();
  }
  result.drain = drain.wait();
  if (result.memory_locked) unlock_memory();
  result.device = device.end_job();
  if (failure) std::rethrow_exception(failure);
  result.ending = classify_ending(result.drain, drain.error(), result.device, options.safe_state);
  return result;
}

}  // namespace mark
