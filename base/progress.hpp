#pragma once
// Cancellation and progress for the long computations of the pipeline: visiting orders,
// toolpaths, V-carving, dot-peen tours, previews. The stages are pure computation (no threads, no
// clocks, no I/O), so all they do is call step() between two items of work; what a step does is
// the caller's business. The command line passes one that throws Interrupted once Ctrl-C was
// pressed and prints progress on stderr for work that runs longer than a second
// (marker/cli/console_progress.hpp); tests and library callers pass Progress::none().
//
// A stage calls step() often enough that a stop takes effect within 100 ms (every item that can
// take longer than a few milliseconds, or every few hundred cheap ones), and never from inside
// a state it could not abandon: Interrupted unwinds, and nothing is half-written because files
// are only written by the commands, after the work.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace mark {

// Thrown by a long computation that noticed a stop request: nothing was finished, nothing was
// written. `where` says what was being done and how far it got.
class Interrupted : public std::runtime_error {
 public:
  Interrupted() : std::runtime_error("interrupted; nothing was written") {}
  explicit Interrupted(const std::string& where)
      : std::runtime_error("interrupted while " + where + "; nothing was written") {}
};

class Progress {
 public:
  virtual ~Progress() = default;
  // Between two items of `task` ("ordering 4160 strokes", "v-carving letters"): `done` of
  // `total` are finished (total 0: not known). Throws Interrupted when a stop was requested.
  virtual void step(std::string_view task, std::size_t done, std::size_t total) const = 0;

  // Never stops, reports nothing.
  static const Progress& none();
};

namespace detail {
struct NoProgress final : Progress {
  void step(std::string_view, std::size_t, std::size_t) const override {}
};
}  // namespace detail

inline const Progress& Progress::none() {
  static const detail::NoProgress n;
  return n;
}

}  // namespace mark
