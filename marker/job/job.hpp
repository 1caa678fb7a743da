#pragma once
// The main job: text → layout → plan → device. On a sample-level device (the simulated scanner,
// a point DAC) the plan goes on through the locus generator into the line memory, which the
// fixed-rate drain reads out (with the laser delay line) while the producer is still writing it
// — in real time by default. On a command-level device (a vector board) the plan becomes device
// commands that the board executes on its own clock, with the pen's delays set on the board.
//
// Every refusal (empty text, a job leaving the field, a speed or tick outside the head's
// limits, a coordinate outside the device's field) happens before the device is touched. The
// result says how the job ended — done, aborted (a stop request: Ctrl-C, an operator) or failed
// (a fault: underrun, device, transport…) — and for the last two where it stopped and how much
// of the ink had been marked, so the caller can say what was and was not marked.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "driver/device.hpp"
#include "driver/head_model.hpp"
#include "driver/quality.hpp"
#include "driver/sim_scanner.hpp"
#include "fonts/stroke_font.hpp"
#include "marker/layout/layout.hpp"
#include "marker/plan/plan.hpp"
#include "ringbuffer/drain_stats.hpp"
#include "ringbuffer/stop_flag.hpp"

namespace mark {

struct JobSpec {
  std::string text;  // UTF-8; '\n' starts a new line
  std::shared_ptr<const StrokeFont> font;
  LayoutOptions layout;
  HeadModel head = head_sl10();
  Pen pen;
  LaserSettings laser;  // the pen's laser source settings
  StrokeOrder order = StrokeOrder::glyph;
};

// A job laid out, planned and checked: ready to stream.
struct CompiledJob {
  Figure figure;
  Plan plan;
  std::size_t laser_on_ticks = 0;   // the laser delay line's edge delays
  std::size_t laser_off_ticks = 0;
};

// Layout, plan and every refusal. Throws InputError (or MissingGlyphError) naming the problem.
// `level` picks the plan a device of that level takes (command-level: no host delay dwells).
CompiledJob compile_job(const JobSpec& spec, DeviceLevel level = DeviceLevel::samples);

// Fault injection (tests, `marker mark --inject KIND@N`): the drain finds the memory empty from
// sample N on (underrun) or stops at sample N as if cancelled (abort). A device fault at N is
// the device's own option (SimScannerOptions::fault_at).
struct Injection {
  enum class Kind { none, underrun, abort } kind = Kind::none;
  std::uint64_t at = 0;
};

struct JobOptions {
  bool virtual_time = false;          // drain as fast as the device accepts (device time only)
  std::size_t memory_samples = 1u << 16;  // line memory capacity (0.66 s at 100 kHz)
  std::size_t first_block = 256;      // the first write is small so the drain starts early
  std::size_t block = 4096;           // later producer writes
  // Real time: samples stored before the drain's clock starts, on top of the device's own
  // FIFO (DeviceDescription::fifo_samples), so a device with a FIFO never starves. 0 = 2 ms.
  std::size_t lead_samples = 0;
  bool realtime = true;               // real time: ask for SCHED_FIFO and locked memory
  const StopFlag* stop = nullptr;     // stop requests (Ctrl-C); not owned
  Injection inject;
  // Called on the producer thread about every 100 ms with samples out / samples in the job.
  std::function<void(std::uint64_t done, std::uint64_t total)> progress;
};

enum class JobOutcome { done, aborted, failed };
std::string_view to_string(JobOutcome outcome);

struct JobResult {
  JobOutcome outcome = JobOutcome::done;
  std::optional<DeviceFault> fault;  // failed: what stopped the job
  // aborted / failed: the first sample (sample level) or device command (command level) that
  // was not output as planned; the device's laser was off from there on.
  std::uint64_t stopped_at = 0;
  double ink_marked = 1;           // share of the job's ink (lit samples / lit length) output
  std::size_t glyphs = 0;
  std::size_t strokes = 0;
  std::size_t commands = 0;        // plan commands (device commands: device.commands_done)
  std::uint64_t samples = 0;       // handed to the device (locus + delay-line tail + safe samples)
  double mark_time_s = 0;          // device time
  double compile_time_s = 0;       // text to the first sample in the line memory (wall clock)
  double wall_time_s = 0;          // text to the end of the job
  double jump_length_mm = 0;
  DrainStats drain;                // sample level
  bool memory_locked = false;      // real time: the process's pages were locked in RAM
  // A stop request (StopFlag): wall time from the request to the device's laser off, and (sample
  // level, real time) samples the device still got after the request; −1 / 0 without one.
  double stop_latency_us = -1;
  std::uint64_t stop_latency_samples = 0;
  DeviceReport device;
  std::optional<Quality> quality;  // when the device is the simulated scanner
  CompiledJob job;                 // what was marked: figure and plan
};

// Runs the job on any device: compile, begin_job, stream (samples through the drain, or device
// commands), end_job. A device left in a final state by an earlier job is reset first. Throws
// InputError for a refused job (the device untouched) and DeviceFaultError when the device
// cannot start; a fault during the job is in the result (outcome failed), not thrown.
JobResult run_job(const JobSpec& spec, const JobOptions& options, Device& device);
// The simulated scanner for a spec: its head, its pen's tick, lit paths recorded.
SimScannerOptions simulator_options(const JobSpec& spec);
// Runs the job on that scanner and evaluates the quality figures against the figure's intended
// strokes (against `reference` when given — it must be built from this spec's figure; a speed
// search reuses one). The scanner keeps the dose for a preview.
JobResult run_job_simulated(const JobSpec& spec, const JobOptions& options, SimScanner& scanner,
                            const QualityReference* reference = nullptr);

}  // namespace mark
