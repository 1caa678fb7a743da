#pragma once
// The fixed-rate drain: a thread that reads the line memory out to a device in fixed-size blocks
// at a fixed sample rate, paced on std::chrono::steady_clock with absolute deadlines (block k is
// due at start + k·block period; sleep_until then a short spin), so lateness never accumulates.
//
// Underrun (real time only): if the memory holds less than a block when it is due and the
// producer has not closed it, the drain sends what there is and pads the block with
// safe_sample(last) — for a laser the last position with the laser off — counts it and carries on.
// Virtual time drains as fast as the sink accepts; an empty, unclosed memory then means "wait",
// never underrun, because no deadline exists.
//
// The filter (e.g. the laser delay line) sees only samples from the memory: hold samples are
// added after it, so an underrun switches the laser off at once and the filter's ticks resume
// where they stopped.
//
// End: when the memory is closed and empty the drain sends the last (partial) block, then the
// filter's flush tail (e.g. the pending delayed laser-off), and stops. On abort() or an
// exception from the sink it calls sink.halt() (laser off), aborts the memory so the producer
// stops waiting, and join() rethrows the sink's exception.
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <span>
#include <stdexcept>
#include <thread>
#include <vector>

#include "ringbuffer/backoff.hpp"
#include "ringbuffer/drain_stats.hpp"
#include "ringbuffer/lateness_histogram.hpp"
#include "ringbuffer/line_memory.hpp"
#include "ringbuffer/sample_filter.hpp"
#include "ringbuffer/sample_traits.hpp"
#include "ringbuffer/sink.hpp"

namespace mark {

struct DrainOptions {
  double rate_hz = 100000;          // output sample rate (10 µs tick)
  std::size_t block_samples = 100;  // samples per sink write (100 = 1 ms at 100 kHz)
  bool virtual_time = false;        // true: as fast as the sink accepts, no deadlines
  // Real time: the clock starts once this many samples are stored (or the memory is closed),
  // so a job does not open with an underrun. 0 = one block.
  std::size_t start_fill = 0;
  double spin_us = 80;              // wake this long before a deadline and spin the rest
};

template <HasSafeSample T>
class Drain {
 public:
  // The memory, sink and filter (optional) must outlive the drain.
  Drain(LineMemory<T>& memory, Sink<T>& sink, DrainOptions options = {},
        SampleFilter<T>* filter = nullptr)
      : memory_(memory), sink_(sink), filter_(filter), options_(options) {
    if (!(options_.rate_hz > 0)) throw std::invalid_argument("drain rate must be positive");
    if (options_.block_samples == 0) throw std::invalid_argument("drain block must hold a sample");
  }
  Drain(const Drain&) = delete;
  Drain& operator=(const Drain&) = delete;
  ~Drain() {
    if (thread_.joinable()) {
      memory_.abort();
      thread_.join();
    }
  }

  // Launch the drain thread.
  void start() {
    if (thread_.joinable()) throw std::logic_error("drain already started");
    thread_ = std::thread([this] { run(); });
  }

  // Wait for the end of the job (or the abort) and return the statistics; rethrows an
  // exception the sink threw (after the sink was halted).
  DrainStats join() {
    if (thread_.joinable()) thread_.join();
    if (error_) std::rethrow_exception(error_);
    return stats_;
  }

  // Stop now from any thread: the sink is halted (laser off) and the producer released.
  void abort() { memory_.abort(); }

  // Samples handed to the sink so far (for progress displays; any thread).
  std::uint64_t samples_out() const { return samples_out_.load(std::memory_order_relaxed); }

  // Run on the calling thread instead of start()/join() (tests, single-threaded virtual time).
  DrainStats run_here() {
    run();
    return join();
  }

 private:
  using Clock = std::chrono::steady_clock;

  void run() {
    try {
      drain_all();
    } catch (...) {
      error_ = std::current_exception();
      sink_.halt();
      memory_.abort();
    }
    stats_.peak_fill = memory_.peak_fill();
    stats_.lateness_median_us = lateness_.quantile_us(0.5);
    stats_.lateness_p99_us = lateness_.quantile_us(0.99);
    stats_.lateness_max_us = lateness_.max_us();
  }

  void drain_all() {
    const std::size_t B = options_.block_samples;
    std::vector<T> block(B);
    if (!options_.virtual_time && !wait_for_start()) return halt_aborted();

    const auto period = std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(static_cast<double>(B) / options_.rate_hz));
    const auto spin = std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double, std::micro>(options_.spin_us));
    const Clock::time_point t0 = Clock::now();
    std::uint64_t k = 0;
    bool starved = false;

    for (;;) {
      if (memory_.aborted()) return halt_aborted();
      if (!options_.virtual_time) wait_until(t0 + period * k, spin);
      ++k;

      std::size_t n = memory_.pop(std::span<T>(block));
      bool end = false;
      if (n < B) {
        if (options_.virtual_time) {
          n = fill_virtual(block, n, end);
          if (memory_.aborted()) return halt_aborted();
        } else {
          // Read the close flag before popping again: if it was set, every sample the producer
          // stored is visible now, so an empty memory afterwards really is the end.
          const bool closed = memory_.closed();
          n += memory_.pop(std::span<T>(block).subspan(n));
          end = closed && n < B;
        }
      }
      if (n > 0) {
        if (filter_) filter_->apply(std::span<T>(block.data(), n));
        last_ = block[n - 1];
      }
      if (n < B && !end) {  // real-time underrun: pad with hold samples, laser off
        const T hold = safe_sample(last_);
        std::fill(block.begin() + n, block.end(), hold);
        if (!starved) ++stats_.underrun_events;
        stats_.underrun_samples += B - n;
        starved = true;
        n = B;
      } else {
        starved = false;
      }
      if (n > 0) emit(std::span<const T>(block.data(), n));
      if (end) break;
    }

    if (filter_) {
      std::vector<T> tail;
      filter_->flush(last_, tail);
      for (std::size_t i = 0; i < tail.size(); i += B) {
        if (memory_.aborted()) return halt_aborted();
        if (!options_.virtual_time) wait_until(t0 + period * k, spin);
        ++k;
        emit(std::span<const T>(tail).subspan(i, std::min(B, tail.size() - i)));
      }
    }
  }

  // Real time: wait until the memory holds start_fill samples or is closed. False if aborted.
  bool wait_for_start() {
    const std::size_t need =
        std::min(options_.start_fill ? options_.start_fill : options_.block_samples,
                 memory_.capacity());
    Backoff backoff;
    while (memory_.fill() < need && !memory_.closed()) {
      if (memory_.aborted()) return false;
      backoff.pause();
    }
    return !memory_.aborted();
  }

  // Virtual time: complete the block, waiting for the producer; stop short only at the end.
  std::size_t fill_virtual(std::vector<T>& block, std::size_t n, bool& end) {
    Backoff backoff;
    while (n < block.size()) {
      const bool closed = memory_.closed();
      const std::size_t got = memory_.pop(std::span<T>(block).subspan(n));
      n += got;
      if (got > 0) {
        backoff.reset();
        continue;
      }
      if (closed) {
        end = true;
        break;
      }
      if (memory_.aborted()) break;
      backoff.pause();
    }
    return n;
  }

  void wait_until(Clock::time_point deadline, Clock::duration spin) {
    if (Clock::now() < deadline - spin) std::this_thread::sleep_until(deadline - spin);
    Clock::time_point now;
    while ((now = Clock::now()) < deadline) {
    }
    lateness_.add(std::chrono::duration<double, std::micro>(now - deadline).count());
  }

  void emit(std::span<const T> samples) {
    sink_.write(samples);
    ++stats_.blocks;
    stats_.samples_out += samples.size();
    samples_out_.store(stats_.samples_out, std::memory_order_relaxed);
  }

  void halt_aborted() {
    sink_.halt();
    stats_.aborted = true;
  }

  LineMemory<T>& memory_;
  Sink<T>& sink_;
  SampleFilter<T>* filter_;
  DrainOptions options_;
  std::thread thread_;
  std::exception_ptr error_;
  DrainStats stats_;
  LatenessHistogram lateness_;
  T last_{};
  std::atomic<std::uint64_t> samples_out_{0};
};

}  // namespace mark
