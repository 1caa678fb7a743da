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
// of the ink had been marked, so the caller can say what was and was not marked. What was
// marked — quality, pulses, codes read back — comes from the evaluator the caller passes in
// (JobOptions::evaluator, marker/job/mark_evaluator.hpp); the runner does not ask what the device
// is beyond the level it takes.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "driver/device.hpp"
#include "driver/sim/head_model.hpp"
#include "driver/sim/pulse_train.hpp"
#include "driver/sim/quality.hpp"
#include "fonts/stroke_font.hpp"
#include "marker/codes/code_object.hpp"
#include "marker/codes/verify.hpp"
#include "marker/job/code_photo.hpp"
#include "marker/fill/fill_options.hpp"
#include "marker/layout/layout.hpp"
#include "marker/plan/plan.hpp"
#include "ringbuffer/drain_stats.hpp"
#include "ringbuffer/stop_flag.hpp"

namespace mark {

class MarkEvaluator;

struct JobSpec {
  std::string text;  // UTF-8; '\n' starts a new line (may be empty when the job has codes)
  std::shared_ptr<const StrokeFont> font;
  LayoutOptions layout;
  std::optional<FillOptions> fill;  // outline-font letters hatch-filled (marker/fill)
  std::vector<CodeObject> codes;    // codes marked after the text (marker/codes)
  CodeCheckOptions verify;          // material, camera and readers for reading the codes back
  HeadModel head = head_sl10();
  Pen pen;
  LaserSettings laser;  // the pen's laser source settings
  StrokeOrder order = StrokeOrder::glyph;
  int passes = 1;       // the strokes are marked this many times over (marker/plan/passes.hpp)
};

// A job laid out, planned and checked: ready to stream to a device of `level`.
struct CompiledJob {
  DeviceLevel level = DeviceLevel::samples;
  Figure figure;                  // the text's glyphs (filled or not), then one glyph per code
  std::vector<PlacedCode> codes;  // the codes as placed, for their verification
  Plan plan;
  std::size_t laser_on_ticks = 0;   // the laser delay line's edge delays
  std::size_t laser_off_ticks = 0;
};

// Puts what a job-file object marks this time into its spec: the text of a text object, or the
// data of a code object's one code (its \G \R \E \xHH escapes decoded when `code_escapes`).
void set_marked_text(JobSpec& spec, std::string_view text, bool code_escapes);

// What the job marks, before planning: the text laid out (and filled), then each code's marks as
// one more glyph. Every part is refused if it leaves the field (naming it). `codes` receives the
// placed codes when given.
Figure job_figure(const JobSpec& spec, std::vector<PlacedCode>* codes = nullptr,
                  std::string_view field_remedy = {});

// Layout, plan and every refusal. Throws InputError (or MissingGlyphError) naming the problem.
// `level` picks the plan a device of that level takes (command-level: no host delay dwells).
// The parts of a series compile incrementally with a JobCompiler (marker/job/job_compiler.hpp).
// `home` is where a sample-level device's mirrors are when the job starts (its plan's first jump
// starts there). compile_job = plan_job(lay_out_job(spec), …).
CompiledJob compile_job(const JobSpec& spec, DeviceLevel level = DeviceLevel::samples,
                        const Point& home = Point(0, 0));

// A mark is laid out once and planned once for its device: the two halves of compile_job, for a
// caller that needs the figure before the pen is known (the automatic speed comes from the
// figure's tightest curve), and that shares one compile between the quality prediction and the
// run. lay_out_job: the spec's refusals before the layout (text, font, passes), the layout with
// its fill and codes (job_figure), the letters inside the field — `field_remedy`, what the user
// can change, ends that message. The plan is left empty.
CompiledJob lay_out_job(const JobSpec& spec, std::string_view field_remedy = {});
// Plans a laid-out job for `level` with the spec's pen, with every plan refusal (the pen against
// the head, speeds, the field with blanking lines and jumps).
CompiledJob plan_job(CompiledJob laid_out, const JobSpec& spec, DeviceLevel level,
                     const Point& home = Point(0, 0));

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
  // FIFO (DeviceDescription::fifo_samples), so a device with a FIFO never starves. 0 = 50 ms:
  // the producer makes that in tens of µs, but on a loaded machine it can lose the CPU for
  // milliseconds right after the first block (seen: 2 ms was not enough at load 20 on 2 cores);
  // once running, the memory (0.66 s) fills far ahead of the drain.
  std::size_t lead_samples = 0;
  bool realtime = true;               // real time: ask for SCHED_FIFO and locked memory
  const StopFlag* stop = nullptr;     // stop requests (Ctrl-C); not owned
  Injection inject;
  // run_compiled_job: the wall time the caller spent compiling the job it hands over (layout and
  // plan), the first part of JobResult::compile_time_s.
  double compiled_s = 0;
  // Called on the producer thread about every 100 ms with samples out / samples in the job.
  std::function<void(std::uint64_t done, std::uint64_t total)> progress;
  // Tells what was marked (quality, pulses, codes) when the caller has something that can: the
  // simulated scanner it made (marker/job/sim_evaluator.hpp). Not owned; may be null.
  MarkEvaluator* evaluator = nullptr;
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
  std::optional<Quality> quality;  // from the evaluator (the simulated scanner), when given
  std::optional<PulseFigures> pulses;  // from the evaluator
  std::vector<CodeVerification> codes;  // from the evaluator: each code read back off the mark
  CompiledJob job;                 // what was marked: figure and plan
};

// Runs the job on any device: compile, begin_job, stream (samples through the drain, or device
// commands), end_job, then the evaluator (options.evaluator) on what was marked. A device left
// in a final state by an earlier job is reset first. Throws
// InputError for a refused job (the device untouched) and DeviceFaultError when the device
// cannot start; a fault during the job is in the result (outcome failed), not thrown.
JobResult run_job(const JobSpec& spec, const JobOptions& options, Device& device);
// The same for a job compiled beforehand (compile_job or a JobCompiler, for this device's
// level; InputError otherwise): the device's own refusals (its field) are made here.
JobResult run_compiled_job(const JobSpec& spec, CompiledJob job, const JobOptions& options,
                           Device& device);
}  // namespace mark
