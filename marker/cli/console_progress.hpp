#pragma once
// The command line's Progress (base/progress.hpp): every long command (gcode, peen, preview)
// hands one to the stages it runs.
//  * Stop: a step throws Interrupted, naming the task and how far it got, once Ctrl-C / SIGTERM
//    set the command's stop flag (interrupt.hpp). Some work cannot see a step for seconds — one
//    Clipper offset of a whole protrusion plate, a font of 3000 glyphs being fitted — so a
//    watchdog thread ends the process itself 20 ms after the request (exit 130, the same
//    message), unless the command has begun writing its files: files are only written after all
//    the work (atomically, marker/output), so before that moment nothing is half-written.
//  * Progress: once the work has run for a second and a stage has reported a step, the watchdog
//    prints the last step on stderr, once a second (also while one long call runs), until the
//    files are written; not with --json or --quiet (a script reading stdout or a log wants no
//    chatter), and not before the first step (a refusal of the options stays one line).
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>

#include "base/progress.hpp"
#include "ringbuffer/stop_flag.hpp"

namespace mark::cli {

class ConsoleProgress final : public Progress {
 public:
  // `stop`: the flag Ctrl-C sets (interrupt_flag()); `quiet`: no progress lines.
  ConsoleProgress(const StopFlag& stop, bool quiet);
  ~ConsoleProgress() override;
  ConsoleProgress(const ConsoleProgress&) = delete;
  ConsoleProgress& operator=(const ConsoleProgress&) = delete;

  void step(std::string_view task, std::size_t done, std::size_t total) const override;

  // From here on the command writes its files: a stop request is left to the command (it
  // finishes the files it began), the watchdog no longer ends the process.
  void writing_files();

  // "ordering strokes: 1200 of 4160" / "v-carving letters: 12": what a progress line and an
  // interruption message say about a task.
  static std::string describe(std::string_view task, std::size_t done, std::size_t total);

 private:
  void watch();

  const StopFlag& stop_;
  bool quiet_;
  std::int64_t start_ns_;
  std::int64_t next_print_ns_;               // under mutex_
  mutable std::mutex mutex_;
  mutable std::string where_ = "opening the font and laying out the text";  // the last step reported
  // No progress line before a stage has reported: what runs before (options, the font) may
  // still end in a one-line refusal, which stays one line.
  mutable bool reported_ = false;
  std::condition_variable wake_;             // the command is done: the watchdog need not wait out its poll
  bool done_ = false;                        // under mutex_
  bool writing_ = false;                     // under mutex_
  std::thread watchdog_;
};

// The progress of the running command: a ConsoleProgress on interrupt_flag().
ConsoleProgress command_progress(bool quiet);

}  // namespace mark::cli
