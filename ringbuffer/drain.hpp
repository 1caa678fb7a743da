#pragma once
// The fixed-rate drain: a thread that reads the line memory out to a device in fixed-size blocks
// at a fixed sample rate, paced on std::chrono::steady_clock with absolute deadlines (block k is
// due at start + k·block period; sleep_until then a short spin), so lateness never accumulates.
// Virtual time drains as fast as the device accepts; an empty, unclosed memory then means
// "wait", because no deadline exists.
//
// Laser safety, whatever the sample type (its safe sample: laser off, stylus lifted):
// - Underrun (real time: the memory holds less than a block when it is due and the producer has
//   not closed it) is a fault. The samples that are there go out, the rest of the block is safe
//   samples, the device is halted and the job ends `underrun` with the index of the first
//   missing sample. Nothing ever resumes lit: a stroke restarted after a pause is a ruined part.
// - Stop (a StopFlag request — Ctrl-C, an operator — or abort(), or the memory aborted) is
//   checked after every wait, right before a block would go out: the drain emits one safe
//   sample, halts the device and ends `cancelled`, so the laser is out within one block of the
//   request. The latency from request to laser off is measured.
// - A device that throws (a fault) is halted; the job ends `device_fault`, join() rethrows.
// - The end: when the memory is closed and empty the drain sends the last (partial) block, the
//   filter's flush tail (the pending delayed laser-off) and one safe sample.
// On every ending other than the end of the job the memory is aborted, so the producer stops.
//
// The filter (e.g. the laser delay line) sees only samples from the memory; safe samples are
// added after it.
//
// The drain thread never allocates once it runs: the block and the tail are sized here, before
// start(). A drain and its memory are re-armable: after join(), reset the memory and start()
// again for the next job.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <mutex>
#include <span>
#include <stdexcept>
#include <thread>
#include <vector>

#include "ringbuffer/backoff.hpp"
#include "ringbuffer/drain_stats.hpp"
#include "ringbuffer/lateness_histogram.hpp"
#include "ringbuffer/line_memory.hpp"
#include "ringbuffer/realtime.hpp"
#include "ringbuffer/sample_filter.hpp"
#include "ringbuffer/sample_traits.hpp"
#include "ringbuffer/sink.hpp"
#include "ringbuffer/stop_flag.hpp"

namespace mark {

inline constexpr std::uint64_t kNever = UINT64_MAX;

struct DrainOptions {
  double rate_hz = 100000;          // output sample rate (10 µs tick)
  std::size_t block_samples = 100;  // samples per device write (100 = 1 ms at 100 kHz)
  bool virtual_time = false;        // true: as fast as the device accepts, no deadlines
  // Real time: the clock starts once this many samples are stored (or the memory is closed),
  // so a job does not open with an underrun. 0 = one block.
  std::size_t start_fill = 0;
  double spin_us = 80;              // wake this long before a deadline and spin the rest
  // Real time: ask for SCHED_FIFO at this priority for the drain thread (0: don't ask).
  int realtime_priority = 80;
  // Stop requests from outside (Ctrl-C, an operator). Not owned; may be null.
  const StopFlag* stop = nullptr;
  // Fault injection (tests and `marker mark --inject`): from sample `starve_at` on the memory
  // looks empty to the drain (an underrun, in virtual time too); at sample `stop_at` the drain
  // stops as if a stop had been requested there.
  std::uint64_t starve_at = kNever;
  std::uint64_t stop_at = kNever;
};

template <HasSafeSample T>
class Drain {
 public:
  // The memory, sink and filter (optional) must outlive the drain.
  Drain(LineMemory<T>& memory, Sink<T>& sink, DrainOptions options = {},
        SampleFilter<T>* filter = nullptr)
      : memory_(memory), sink_(sink), filter_(filter), options_(options),
        block_(options.block_samples) {
    if (!(options_.rate_hz > 0)) throw std::invalid_argument("drain rate must be positive");
    if (options_.block_samples == 0) throw std::invalid_argument("drain block must hold a sample");
    if (filter_) tail_.reserve(filter_->max_tail());
  }
  Drain(const Drain&) = delete;
  Drain& operator=(const Drain&) = delete;
  ~Drain() {
    if (thread_.joinable()) {
      memory_.abort();
      thread_.join();
    }
  }

  // Launch the drain thread (again, after join(), for the next job).
  void start() {
    if (thread_.joinable()) throw std::logic_error("drain already started");
    stats_ = {};
    error_ = nullptr;
    last_ = T{};
    samples_out_.store(0, std::memory_order_relaxed);
    lateness_ = LatenessHistogram();
    {
      std::lock_guard lock(finished_mutex_);
      finished_ = false;
    }
    thread_ = std::thread([this] { run(); });
  }

  // Wait for the end of the job (or the stop, underrun or fault) and return the statistics;
  // rethrows an exception the device threw (after the device was halted).
  DrainStats join() {
    if (thread_.joinable()) thread_.join();
    if (error_) std::rethrow_exception(error_);
    return stats_;
  }

  // Like join(), but an exception the device threw stays in error() instead of being rethrown:
  // the statistics of a faulted job are wanted too.
  DrainStats wait() {
    if (thread_.joinable()) thread_.join();
    return stats_;
  }
  std::exception_ptr error() const { return error_; }

  // True once the drain thread has ended (the job done, stopped, underrun or faulted), waiting up
  // to `timeout` for it: a progress display wakes at the end instead of sleeping its period out
  // (a fixed sleep added up to 100 ms to every mark's latency).
  template <class Rep, class Period>
  bool finished_within(std::chrono::duration<Rep, Period> timeout) {
    std::unique_lock lock(finished_mutex_);
    return finished_cv_.wait_for(lock, timeout, [&] { return finished_; });
  }

  // Stop now from any thread: the device gets a safe sample and is halted, the producer released.
  void abort() { memory_.abort(); }

  // Samples handed to the device so far (for progress displays; any thread).
  std::uint64_t samples_out() const { return samples_out_.load(std::memory_order_relaxed); }

  // Run on the calling thread instead of start()/join() (tests, single-threaded virtual time).
  DrainStats run_here() {
    stats_ = {};
    error_ = nullptr;
    run();
    if (error_) std::rethrow_exception(error_);
    return stats_;
  }

 private:
  using Clock = std::chrono::steady_clock;

  void run() {
    if (!options_.virtual_time && options_.realtime_priority > 0)
      stats_.realtime_granted = request_realtime_priority(options_.realtime_priority);
    try {
      drain_all();
    } catch (...) {
      error_ = std::current_exception();
      stats_.end = DrainEnd::device_fault;
      stats_.stop_sample = stats_.samples_out;
      sink_.halt();
      memory_.abort();
    }
    stats_.peak_fill = memory_.peak_fill();
    stats_.lateness_median_us = lateness_.quantile_us(0.5);
    stats_.lateness_p99_us = lateness_.quantile_us(0.99);
    stats_.lateness_max_us = lateness_.max_us();
    {
      std::lock_guard lock(finished_mutex_);
      finished_ = true;
    }
    finished_cv_.notify_all();
  }

  bool stop_requested() const {
    return memory_.aborted() || (options_.stop && options_.stop->requested());
  }
  // The injected stop point is reached once the current block holds `n` samples.
  bool at_stop_point(std::size_t n) const { return stats_.samples_out + n >= options_.stop_at; }

  // How many of `want` samples the drain may take from the memory when `from` samples of the
  // current block are already taken: all of them, or up to the injected starvation point.
  std::size_t takeable(std::size_t from, std::size_t want) const {
    const std::uint64_t limit = std::min(options_.starve_at, options_.stop_at);
    if (limit == kNever) return want;
    const std::uint64_t taken = stats_.samples_out + from;
    return taken >= limit ? 0
                          : static_cast<std::size_t>(std::min<std::uint64_t>(want, limit - taken));
  }

  std::size_t pop(std::size_t from, std::size_t to) {
    const std::size_t n = takeable(from, to - from);
    return n ? memory_.pop(std::span<T>(block_).subspan(from, n)) : 0;
  }

  void drain_all() {
    const std::size_t B = options_.block_samples;
    t0_ = Clock::now();
    if (!options_.virtual_time && !wait_for_start()) return stop();

    const auto period = std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(static_cast<double>(B) / options_.rate_hz));
    spin_ = std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double, std::micro>(options_.spin_us));
    t0_ = Clock::now();
    std::uint64_t k = 0;

    for (;;) {
      if (!options_.virtual_time) wait_until(t0_ + period * k);
      ++k;
      if (stop_requested()) return stop();  // after the wait: a request during it counts now

      std::size_t n = pop(0, B);
      bool end = false;
      if (n < B && !at_stop_point(n)) {
        if (options_.virtual_time) {
          n = fill_virtual(n, end);
          if (stop_requested()) return stop();
        } else {
          // Read the close flag before popping again: if it was set, every sample the producer
          // stored is visible now, so an empty memory afterwards really is the end.
          const bool closed = memory_.closed();
          n += pop(n, B);
          end = closed && n < B && memory_.readable() == 0;
        }
      }
      if (n > 0) {
        if (filter_) filter_->apply(std::span<T>(block_.data(), n));
        last_ = block_[n - 1];
      }
      if (at_stop_point(n)) {
        if (n > 0) emit(std::span<const T>(block_.data(), n));
        return stop();
      }
      if (n < B && !end) return underrun(n);
      if (n > 0) emit(std::span<const T>(block_.data(), n));
      if (end) break;
    }

    if (filter_) {
      tail_.clear();
      filter_->flush(last_, tail_);
      for (std::size_t i = 0; i < tail_.size(); i += B) {
        if (!options_.virtual_time) wait_until(t0_ + period * k);
        ++k;
        if (stop_requested()) return stop();
        emit(std::span<const T>(tail_).subspan(i, std::min(B, tail_.size() - i)));
        last_ = tail_[std::min(tail_.size(), i + B) - 1];
      }
    }
    emit_safe(1);
    stats_.end = DrainEnd::completed;
  }

  // The memory ran dry mid-job: what there is goes out, then safe samples to the end of the
  // block (the device keeps its clock), then the device is halted. The job is over.
  void underrun(std::size_t n) {
    stats_.end = DrainEnd::underrun;
    stats_.stop_sample = stats_.samples_out + n;
    stats_.underrun_events = 1;
    stats_.underrun_samples = options_.block_samples - n;
    const T safe = safe_sample(last_);
    std::fill(block_.begin() + static_cast<std::ptrdiff_t>(n), block_.end(), safe);
    emit(std::span<const T>(block_.data(), block_.size()));
    sink_.halt();
    memory_.abort();
  }

  // A stop request: one safe sample, then halt. The latency is measured from the request.
  void stop() {
    stats_.end = DrainEnd::cancelled;
    stats_.stop_sample = stats_.samples_out;
    emit_safe(1);
    sink_.halt();
    if (options_.stop && options_.stop->requested()) {
      const std::int64_t asked = options_.stop->requested_at_ns();
      const std::int64_t now = StopFlag::now_ns();
      if (asked > 0 && now >= asked) stats_.stop_latency_us = static_cast<double>(now - asked) / 1e3;
      if (!options_.virtual_time && asked > 0) {
        // Where the request fell on the device's sample clock, and how many samples went out
        // after it (the real-time drain's clock is the device's).
        const std::int64_t t0 = std::chrono::duration_cast<std::chrono::nanoseconds>(
                                    t0_.time_since_epoch()).count();
        const double at = static_cast<double>(asked - t0) * 1e-9 * options_.rate_hz;
        const double after = static_cast<double>(stats_.stop_sample) - std::max(0.0, at);
        stats_.stop_latency_samples = static_cast<std::uint64_t>(std::max(0.0, after));
      }
    }
    memory_.abort();
  }

  void emit_safe(std::size_t count) {
    const T safe = safe_sample(last_);
    const std::size_t n = std::min(count, block_.size());
    std::fill(block_.begin(), block_.begin() + static_cast<std::ptrdiff_t>(n), safe);
    emit(std::span<const T>(block_.data(), n));
  }

  // Real time: wait until the memory holds start_fill samples or is closed. False if stopped.
  bool wait_for_start() {
    const std::size_t need =
        std::min(options_.start_fill ? options_.start_fill : options_.block_samples,
                 memory_.capacity());
    Backoff backoff;
    while (memory_.fill() < need && !memory_.closed()) {
      if (stop_requested()) return false;
      backoff.pause();
    }
    t0_ = Clock::now();
    return !stop_requested();
  }

  // Virtual time: complete the block, waiting for the producer; stop short only at the end or
  // at an injected starvation point (then it is an underrun).
  std::size_t fill_virtual(std::size_t n, bool& end) {
    Backoff backoff;
    while (n < block_.size()) {
      const bool closed = memory_.closed();
      const std::size_t got = pop(n, block_.size());
      n += got;
      if (got > 0) {
        backoff.reset();
        continue;
      }
      if (closed && memory_.readable() == 0) {
        end = true;
        break;
      }
      if (takeable(n, 1) == 0) break;  // injected starvation (an underrun) or stop point
      if (stop_requested()) break;
      backoff.pause();
    }
    return n;
  }

  void wait_until(Clock::time_point deadline) {
    if (Clock::now() < deadline - spin_) std::this_thread::sleep_until(deadline - spin_);
    Clock::time_point now;
    while ((now = Clock::now()) < deadline) {
    }
    lateness_.add(std::chrono::duration<double, std::micro>(now - deadline).count());
  }

  void emit(std::span<const T> samples) {
    if (stats_.blocks == 0) stats_.first_write = Clock::now();
    sink_.write(samples);
    ++stats_.blocks;
    stats_.samples_out += samples.size();
    samples_out_.store(stats_.samples_out, std::memory_order_relaxed);
  }

  LineMemory<T>& memory_;
  Sink<T>& sink_;
  SampleFilter<T>* filter_;
  DrainOptions options_;
  std::vector<T> block_;
  std::vector<T> tail_;
  std::thread thread_;
  std::exception_ptr error_;
  DrainStats stats_;
  LatenessHistogram lateness_;
  T last_{};
  Clock::time_point t0_{};
  Clock::duration spin_{};
  std::atomic<std::uint64_t> samples_out_{0};
  std::mutex finished_mutex_;
  std::condition_variable finished_cv_;
  bool finished_ = false;
};

}  // namespace mark
