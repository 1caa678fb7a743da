#include "marker/cli/console_progress.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "marker/cli/interrupt.hpp"

namespace mark::cli {
namespace {

constexpr std::int64_t kSecond_ns = 1'000'000'000;
// After a stop request the stages get this long to stop at a step of their own; then the
// watchdog ends the process. Together with its polling period, well inside the 100 ms a stop
// may take.
constexpr std::int64_t kGrace_ns = 20'000'000;
constexpr auto kPoll = std::chrono::milliseconds(2);

}  // namespace

ConsoleProgress::ConsoleProgress(const StopFlag& stop, bool quiet)
    : stop_(stop), quiet_(quiet), start_ns_(StopFlag::now_ns()), next_print_ns_(start_ns_ + kSecond_ns),
      watchdog_([this] { watch(); }) {}

ConsoleProgress::~ConsoleProgress() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
  }
  wake_.notify_all();
  watchdog_.join();
}

std::string ConsoleProgress::describe(std::string_view task, std::size_t done, std::size_t total) {
  std::string s(task);
  s += ": " + std::to_string(done);
  if (total > 0) s += " of " + std::to_string(total);
  return s;
}

void ConsoleProgress::step(std::string_view task, std::size_t done, std::size_t total) const {
  std::string where = describe(task, done, total);
  if (stop_.requested()) throw Interrupted(where);
  const std::lock_guard<std::mutex> lock(mutex_);
  where_ = std::move(where);
  reported_ = true;
}

// Under the lock the watchdog holds while it decides: it either ends the process before the first
// byte is written, or sees this and never does.
void ConsoleProgress::writing_files() {
  const std::lock_guard<std::mutex> lock(mutex_);
  writing_ = true;
}

// The watchdog also prints the progress lines: the last step the work reported, once a second,
// so a long call that cannot report (a Clipper offset) still shows where the command is.
void ConsoleProgress::watch() {
  std::unique_lock<std::mutex> lock(mutex_);
  while (!done_) {
    wake_.wait_for(lock, kPoll);
    if (done_) return;
    const std::int64_t now = StopFlag::now_ns();
    if (!quiet_ && !writing_ && reported_ && now >= next_print_ns_) {
      next_print_ns_ = now + kSecond_ns;
      std::fprintf(stderr, "marker: %s (%lld s)\n", where_.c_str(), static_cast<long long>((now - start_ns_) / kSecond_ns));
    }
    if (!stop_.requested() || writing_) continue;
    if (StopFlag::now_ns() - stop_.requested_at_ns() < kGrace_ns) continue;
    const std::string where = where_;
    // The work is stuck in one long call: nothing has been written, so the process may end here.
    std::fprintf(stderr, "marker: %s\n", Interrupted(where).what());
    std::fflush(stderr);
    std::_Exit(kExitInterrupted);
  }
}

ConsoleProgress command_progress(bool quiet) { return ConsoleProgress(interrupt_flag(), quiet); }

}  // namespace mark::cli
