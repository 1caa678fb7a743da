#pragma once
// The main job: text → layout → plan → locus → line memory → drain (with the laser delay line)
// → device. The producer (layout, planner, locus generator) runs on the calling thread and
// writes the line memory block by block while the drain thread reads it out at the device rate
// — in real time by default, so the memory really is written while it is read. Every refusal
// (empty text, a job leaving the field, a speed or tick outside the head's limits) happens
// before the first sample.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "driver/head_model.hpp"
#include "driver/quality.hpp"
#include "driver/sim_scanner.hpp"
#include "fonts/stroke_font.hpp"
#include "marker/layout/layout.hpp"
#include "marker/plan/plan.hpp"
#include "ringbuffer/drain_stats.hpp"
#include "ringbuffer/sink.hpp"

namespace mark {

struct JobSpec {
  std::string text;  // UTF-8; '\n' starts a new line
  std::shared_ptr<const StrokeFont> font;
  LayoutOptions layout;
  HeadModel head = head_sl10();
  Pen pen;
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
CompiledJob compile_job(const JobSpec& spec);

struct JobOptions {
  bool virtual_time = false;          // drain as fast as the device accepts (device time only)
  std::size_t memory_samples = 1u << 16;  // line memory capacity (0.66 s at 100 kHz)
  std::size_t first_block = 256;      // the first write is small so the drain starts early
  std::size_t block = 4096;           // later producer writes
  // Called on the producer thread about every 100 ms with samples out / samples in the job.
  std::function<void(std::uint64_t done, std::uint64_t total)> progress;
};

struct JobResult {
  std::size_t glyphs = 0;
  std::size_t strokes = 0;
  std::size_t commands = 0;
  std::uint64_t samples = 0;      // handed to the device (locus + delay-line tail + underrun holds)
  double mark_time_s = 0;         // device time: samples × tick
  double compile_time_s = 0;      // text to the first sample in the line memory (wall clock)
  double wall_time_s = 0;         // text to the end of the drain
  double jump_length_mm = 0;
  DrainStats drain;
  std::optional<Quality> quality;  // when the device is the simulated scanner
  CompiledJob job;                 // what was marked: figure and plan
};

// Runs the job on any device.
JobResult run_job(const JobSpec& spec, const JobOptions& options, Sink<ScanSample>& device);
// The simulated scanner for a spec: its head, its pen's tick, lit paths recorded.
SimScannerOptions simulator_options(const JobSpec& spec);
// Runs the job on that scanner and evaluates the quality figures against the figure's intended
// strokes (against `reference` when given — it must be built from this spec's figure; a speed
// search reuses one). The scanner keeps the dose for a preview.
JobResult run_job_simulated(const JobSpec& spec, const JobOptions& options, SimScanner& scanner,
                            const QualityReference* reference = nullptr);

}  // namespace mark
