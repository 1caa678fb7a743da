#include "marker/job/simulate_plan.hpp"

#include <vector>

#include "driver/sim/head_model.hpp"
#include "marker/job/job_run.hpp"
#include "marker/job/sim_evaluator.hpp"
#include "marker/locus/locus_generator.hpp"
#include "ringbuffer/laser_delay_line.hpp"

namespace mark {

SimulatedMark simulate_plan(const Plan& plan, SimScanner& scanner) {
  const Pen& pen = plan.pen;
  LaserDelayLine delay(pen.ticks(pen.laser_on_delay_s), pen.ticks(pen.laser_off_delay_s));
  LocusGenerator locus(plan.commands, pen.tick_s);
  std::vector<ScanSample> block(4096);
  ScanSample last{};
  const std::uint64_t before = scanner.samples();
  while (std::size_t n = locus.generate(block.data(), block.size())) {
    delay.apply(std::span<ScanSample>(block.data(), n));
    scanner.write(std::span<const ScanSample>(block.data(), n));
    last = block[n - 1];
  }
  std::vector<ScanSample> tail;
  delay.flush(last, tail);
  if (!tail.empty()) scanner.write(tail);
  SimulatedMark m;
  m.samples = scanner.samples() - before;
  m.mark_time_s = static_cast<double>(m.samples) * pen.tick_s;
  return m;
}

SimScannerOptions simulator_options(const HeadModel& head, const Pen& pen) {
  SimScannerOptions o;
  o.head = head;
  // A preset scans its own field: a job's field larger than that (--field, a job file's
  // field_mm) is the job's, not the head's, so the device refuses it rather than marking as if
  // the head reached that far.
  if (const auto preset = find_head(head.name); preset && head.field_mm > preset->field_mm)
    o.head.field_mm = preset->field_mm;
  o.tick_s = pen.tick_s;
  o.record_lit_paths = true;
  return o;
}

SimulatedJob simulate_job(const JobSpec& spec) {
  SimulatedJob r;
  r.job = compile_job(spec);
  r.scanner = std::make_unique<SimScanner>(simulator_options(spec.head, spec.pen));
  // A job as a device runs one: its pen's power and pulses (so the part's picture has its
  // pulses), its lit paths reserved.
  r.scanner->begin_job(job_header(spec, r.job, r.scanner->describe()));
  r.mark = simulate_plan(r.job.plan, *r.scanner);
  r.scanner->end_job();
  r.codes = verify_codes(spec, r.job, r.scanner->picture_dose());
  return r;
}

}  // namespace mark
