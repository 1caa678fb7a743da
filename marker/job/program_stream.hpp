#pragma once
// A command-level job's device program, handed out while it is being converted: a worker
// thread turns the plan into device commands while the caller passes the first ones on (to a
// board that encodes them into packets), so on two cores the conversion and the encoding
// overlap instead of adding up (40 rows of text, plan → LMC packets: bench/bench_lmc.cpp).
//
// The field check still comes before anything is handed out: commands go out before the
// conversion ends only when the plan's conservative reach (count_program: lines' ends, arcs'
// whole circles) lies in the field with a margin, so no point of it can be refused; any other
// plan is converted whole while the constructor waits, and a point outside the field throws
// from the constructor, before begin_job, as device_program does. Small plans are converted
// whole on the calling thread: a thread costs more than they do (a start and join is ~40 µs
// here). A timed pen's program (timed_moves.hpp) is made whole in the constructor.
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <span>
#include <thread>

#include "marker/job/device_program.hpp"

namespace mark {

enum class StreamMode {
  automatic,  // a worker for plans of at least kStreamMinPlanCommands commands, on 2+ cores
  whole,      // convert everything in the constructor (one thread)
  worker      // a worker whatever the plan's size (tests)
};
inline constexpr std::size_t kStreamMinPlanCommands = 4096;

class ProgramStream {
 public:
  // `plan` must outlive the stream.
  ProgramStream(const Plan& plan, const LaserSettings& laser, const DeviceDescription& device,
                StreamMode mode = StreamMode::automatic);
  ~ProgramStream();  // waits for the worker
  ProgramStream(const ProgramStream&) = delete;
  ProgramStream& operator=(const ProgramStream&) = delete;

  const DevicePen& pen() const { return program_.pen; }
  // Whether commands are handed out while the worker still converts (the plan was big enough
  // and lay in the field).
  bool streaming() const { return streaming_; }

  // Commands from index `from` on, at most `max` of them: waits until at least one is
  // converted; empty when the program ends before `from`. Rethrows what the conversion threw
  // once `from` reaches the point where it stopped.
  std::span<const DeviceCommand> next(std::size_t from, std::size_t max);

  // Waits for the conversion and hands the whole program over (as far as it got, if it
  // threw); the stream is empty afterwards.
  DeviceProgram finish();

 private:
  enum Go : int { wait, stream, whole, quit };
  void convert_here();
  void publish_whole();  // program_ is complete: hand all of it out
  void work(std::size_t half);
  void convert(const std::function<void(std::size_t)>& progress, std::size_t every);
  void start(Go go) { go_.store(go, std::memory_order_release); }
  template <class Done>
  static void wait_until(Done&& done);

  const Plan& plan_;
  const DeviceDescription device_;
  DeviceProgram program_;
  ProgramCount count_;
  ProgramCount second_;  // the worker's count of the plan's second half
  bool streaming_ = false;
  // The worker writes program_.commands (reserved, never reallocated) and publishes how many
  // are complete; the caller reads below that count only, through data_.
  const DeviceCommand* data_ = nullptr;
  // On cache lines of their own: the caller polls them while the worker pushes commands, and
  // next to program_'s end pointer every push took the line away from the poller and back.
  alignas(64) std::atomic<std::size_t> converted_{0};
  std::atomic<bool> ended_{false};
  std::atomic<bool> counted_{false};
  std::atomic<int> go_{wait};
  alignas(64) std::exception_ptr error_;  // written by the worker before ended_
  std::thread worker_;
};

}  // namespace mark
