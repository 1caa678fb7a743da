#pragma once
// The line memory of the seed: a single-producer single-consumer queue of samples that the
// locus generator writes while the drain reads it out at a fixed rate. Built on
// boost::lockfree::spsc_queue. The producer waits while the memory is full; no sample is ever
// dropped or reordered. close() marks the end of the job; abort() wakes and stops both sides; reset() re-arms it.
//
// Threading: push*/close() from the one producer thread, pop() from the one consumer thread;
// fill(), peak_fill(), closed(), aborted(), abort() from anywhere.
#include <algorithm>
#include <atomic>
#include <boost/lockfree/spsc_queue.hpp>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>

#include "ringbuffer/backoff.hpp"

namespace mark {

template <class T>
class LineMemory {
 public:
  // capacity: samples the memory holds (≥ 1).
  explicit LineMemory(std::size_t capacity) : queue_(check_capacity(capacity)), capacity_(capacity) {}
  LineMemory(const LineMemory&) = delete;
  LineMemory& operator=(const LineMemory&) = delete;

  // Producer: append one sample, waiting while full. Returns false (sample not stored) if the
  // memory was aborted — the producer should stop then.
  bool push(const T& sample) { return push(std::span<const T>(&sample, 1)); }

  // Producer: append all samples in order, waiting while full. Returns false if aborted before
  // all were stored (those already stored stay stored).
  bool push(std::span<const T> samples) {
    if (aborted_.load(std::memory_order_acquire)) return false;
    Backoff backoff;
    while (!samples.empty()) {
      if (aborted_.load(std::memory_order_acquire)) return false;
      const std::size_t n = queue_.push(samples.data(), samples.size());
      if (n == 0) {
        backoff.pause();
        continue;
      }
      backoff.reset();
      pushed_.store(pushed_.load(std::memory_order_relaxed) + n, std::memory_order_release);
      samples = samples.subspan(n);
    }
    return true;
  }

  // Producer: no more samples will come (end of job). The consumer drains what is left.
  void close() { closed_.store(true, std::memory_order_release); }

  // Anyone: stop both sides now; a waiting push returns false, the drain halts its device.
  void abort() { aborted_.store(true, std::memory_order_release); }

  // Empty the memory and clear close / abort for the next job (a station reuses one memory
  // for months). Only while neither the producer nor the consumer is using it.
  void reset() {
    queue_.reset();
    pushed_.store(0, std::memory_order_relaxed);
    popped_.store(0, std::memory_order_relaxed);
    peak_fill_.store(0, std::memory_order_relaxed);
    closed_.store(false, std::memory_order_relaxed);
    aborted_.store(false, std::memory_order_release);
  }

  // Consumer: take up to out.size() samples, oldest first; returns how many. Never waits.
  std::size_t pop(std::span<T> out) {
    const std::size_t available = queue_.read_available();
    if (available > peak_fill_.load(std::memory_order_relaxed))
      peak_fill_.store(available, std::memory_order_relaxed);
    const std::size_t n = queue_.pop(out.data(), std::min(out.size(), available));
    popped_.store(popped_.load(std::memory_order_relaxed) + n, std::memory_order_release);
    return n;
  }

  // Consumer: samples ready to pop.
  std::size_t readable() const { return queue_.read_available(); }

  // Samples stored and not yet popped (a consistent-enough snapshot from any thread).
  std::size_t fill() const {
    const std::uint64_t popped = popped_.load(std::memory_order_acquire);
    const std::uint64_t pushed = pushed_.load(std::memory_order_acquire);
    return pushed >= popped ? static_cast<std::size_t>(pushed - popped) : 0;
  }
  // Highest fill the consumer has seen when popping.
  std::size_t peak_fill() const { return peak_fill_.load(std::memory_order_relaxed); }
  std::size_t capacity() const { return capacity_; }
  std::uint64_t pushed() const { return pushed_.load(std::memory_order_acquire); }
  std::uint64_t popped() const { return popped_.load(std::memory_order_acquire); }
  bool closed() const { return closed_.load(std::memory_order_acquire); }
  bool aborted() const { return aborted_.load(std::memory_order_acquire); }

 private:
  static std::size_t check_capacity(std::size_t capacity) {
    if (capacity == 0) throw std::invalid_argument("line memory capacity must be at least 1 sample");
    return capacity;
  }

  boost::lockfree::spsc_queue<T> queue_;
  std::size_t capacity_;
  // Counters on their own cache lines: each is written by one side only.
  alignas(64) std::atomic<std::uint64_t> pushed_{0};
  alignas(64) std::atomic<std::uint64_t> popped_{0};
  alignas(64) std::atomic<std::size_t> peak_fill_{0};
  alignas(64) std::atomic<bool> closed_{false};
  std::atomic<bool> aborted_{false};
};

}  // namespace mark
