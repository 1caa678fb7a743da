#include "marker/job/program_stream.hpp"

#include <algorithm>
#include <limits>
#include <system_error>

#include "marker/job/timed_moves.hpp"

namespace mark {
namespace {

// How many converted commands the worker lets through at a time: a board's chunk (the job
// runner submits 256), so the consumer is rarely more than one chunk behind.
constexpr std::size_t kPublishEvery = 256;
constexpr std::size_t kNoIndex = std::numeric_limits<std::size_t>::max();

}  // namespace

// The other side is microseconds away (a chunk's conversion, half a count): yield, not sleep.
template <class Done>
void ProgramStream::wait_until(Done&& done) {
  while (!done()) std::this_thread::yield();
}

void ProgramStream::convert(const std::function<void(std::size_t)>& progress, std::size_t every) {
  convert_program(plan_, device_, count_, program_, progress, every);
}

ProgramStream::ProgramStream(const Plan& plan, const LaserSettings& laser,
                             const DeviceDescription& device, StreamMode mode)
    : plan_(plan), device_(device) {
  if (timed_on_board(plan.pen)) {
    // The locus as timed moves: made whole here (a field refusal before the job begins), on
    // this thread — it runs the locus generator, which is the sample-level path's producer too.
    program_ = timed_program(plan, laser, device);
    publish_whole();
    return;
  }
  program_.pen = device_pen(plan.pen, laser, DeviceLevel::commands);
  const std::size_t size = plan.commands.size();
  const bool worth_a_thread =
      mode == StreamMode::worker ||
      (mode == StreamMode::automatic && size >= kStreamMinPlanCommands &&
       std::thread::hardware_concurrency() >= 2);
  if (!worth_a_thread) {
    convert_here();
    return;
  }
  // The worker starts first and counts the plan's second half while this thread counts the
  // first (the count reads the whole plan, megabytes: half each halves the wait); then it
  // converts once told whether the plan lies in the field.
  const std::size_t half = size / 2;
  try {
    worker_ = std::thread([this, half] { work(half); });
  } catch (const std::system_error&) {
    convert_here();  // no thread to be had: the part is still marked, converted on this one
    return;
  }
  try {
    count_ = count_program(plan_, device_, 0, half);
    wait_until([&] { return counted_.load(std::memory_order_acquire); });
    if (error_) std::rethrow_exception(error_);
    count_.commands += second_.commands;
    count_.chords.insert(count_.chords.end(), second_.chords.begin(), second_.chords.end());
    count_.inside_field = count_.inside_field && second_.inside_field;
    program_.commands.reserve(count_.commands + 1);
    data_ = program_.commands.data();
  } catch (...) {
    start(quit);
    worker_.join();
    throw;
  }
  streaming_ = count_.inside_field;
  start(streaming_ ? stream : whole);
  if (streaming_) return;
  // A plan that may leave the field is converted whole before anything is handed out, so a
  // point outside it is refused here, before the job begins.
  worker_.join();
  if (error_) std::rethrow_exception(error_);
}

void ProgramStream::convert_here() {
  // Whole, on the calling thread: a refusal throws before the caller has seen a command.
  count_ = count_program(plan_, device_);
  program_.commands.reserve(count_.commands + 1);
  convert({}, kNoIndex);
  publish_whole();
}

void ProgramStream::publish_whole() {
  data_ = program_.commands.data();
  converted_.store(program_.commands.size(), std::memory_order_relaxed);
  ended_.store(true, std::memory_order_relaxed);
}

void ProgramStream::work(std::size_t half) {
  try {
    second_ = count_program(plan_, device_, half, plan_.commands.size());
  } catch (...) {
    error_ = std::current_exception();  // the main thread rethrows it and says quit
  }
  counted_.store(true, std::memory_order_release);
  wait_until([&] { return go_.load(std::memory_order_acquire) != wait; });
  const Go go = static_cast<Go>(go_.load(std::memory_order_acquire));
  if (go == quit) return;
  try {
    if (go == stream) {
      convert([this](std::size_t n) { converted_.store(n, std::memory_order_release); },
              kPublishEvery);
    } else {
      convert({}, kNoIndex);
    }
  } catch (...) {
    error_ = std::current_exception();
  }
  converted_.store(program_.commands.size(), std::memory_order_release);
  ended_.store(true, std::memory_order_release);
}

ProgramStream::~ProgramStream() {
  if (worker_.joinable()) worker_.join();
}

std::span<const DeviceCommand> ProgramStream::next(std::size_t from, std::size_t max) {
  for (;;) {
    // ended_ before converted_: once ended, the count read after it is the final one.
    const bool ended = ended_.load(std::memory_order_acquire);
    const std::size_t have = converted_.load(std::memory_order_acquire);
    if (have > from) return {data_ + from, std::min(max, have - from)};
    if (ended) {
      if (error_) std::rethrow_exception(error_);
      return {};
    }
    std::this_thread::yield();
  }
}

DeviceProgram ProgramStream::finish() {
  if (worker_.joinable()) worker_.join();
  converted_.store(0, std::memory_order_relaxed);
  data_ = nullptr;
  return std::move(program_);
}

}  // namespace mark
