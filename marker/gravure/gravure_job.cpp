#include "marker/gravure/gravure_job.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "base/error.hpp"
#include "driver/sim/stylus_cells.hpp"

#include "marker/gravure/head_design.hpp"
#include "marker/gravure/image_cells.hpp"
#include "marker/limits/gravure_settings.hpp"

namespace mark {
namespace {

// One engraving of the whole job on the head, with or without filters, measured against the
// intended cut.
EngravingResult engrave(ImageCells& cells, const ToolpathOptions& toolpath_options, const FilterBank* bank,
                        const StylusHeadModel& design_head, SimStylusHead& head, const StylusRunOptions& run,
                        const std::vector<float>& intended, const std::vector<CellFigures>& intended_cells,
                        const std::vector<float>& cell_depths, std::vector<float>* keep_profile) {
  EngravingResult r;
  r.advance_samples = latency_samples(bank ? *bank : FilterBank{}, design_head);
  ToolpathOptions options = toolpath_options;
  options.advance_samples = r.advance_samples;
  cells.rewind();
  StylusToolpath toolpath(cells, options);
  StylusRunOptions o = run;
  o.job_name = bank ? "gravure (filtered)" : "gravure (unfiltered)";
  r.run = run_stylus_job(toolpath, bank, head, o);
  r.counts = toolpath.counts();
  head.reset();
  if (r.run.fault) throw DeviceFaultError(*r.run.fault);
  r.depth_error = depth_error(head.cut_profile_um(), intended);
  r.cell_error = cell_error(head.cells(), intended_cells);
  r.depth_error_vs_cells = cell_depth_error(head.cells(), cell_depths);
  r.drive_peak_um = head.drive_peak_um();
  r.max_cut_um = head.max_cut_um();
  if (keep_profile) *keep_profile = head.cut_profile_um();
  return r;
}

}  // namespace

std::string_view to_string(FilterChoice c) {
  switch (c) {
    case FilterChoice::nominal: return "nominal";
    case FilterChoice::tuned: return "tuned";
    case FilterChoice::manual: return "manual";
    case FilterChoice::off: return "off";
  }
  return "?";
}

// The job's length is known from the image's size before any of it is computed: refuse here,
// from that estimate, a job the simulated head would refuse only after the toolpath (4 B per
// sample, twice) had been built — a 200 px image at 0.5 px/mm took 52 s and 1.2 GB to be told so.
void check_job_length(const ImageCells& cells, const GravureScreen& screen, double px_per_mm,
                      std::uint64_t max_samples) {
  const std::uint64_t samples = first_sample_of_cell(cells.cells(), screen.cell_rate_hz);
  if (samples <= max_samples) return;
  throw InputError("gravure image: " + std::to_string(cells.tracks()) + " tracks of " +
                   std::to_string(cells.cells_per_track()) + " cells at " + format_number(px_per_mm) +
                   " px/mm make " + std::to_string(samples) + " stylus samples; the simulated head records at most " +
                   std::to_string(max_samples) + " (" + format_number(std::floor(max_samples / kStylusRate_hz)) +
                   " s): raise --resolution or use a smaller image");
}

GravureReport run_gravure_job(const GravureJobSpec& spec) {
  const auto t0 = std::chrono::steady_clock::now();
  GravureReport report;
  validate(spec.setup);
  validate(spec.screen);
  check_range("stylus angle", spec.stylus_angle_deg, kStylusAngle.range());
  report.px_per_mm = spec.px_per_mm > 0 ? spec.px_per_mm : 4 * spec.screen.cells_per_mm_along;
  ImageCells cells(spec.image, spec.mask ? &*spec.mask : nullptr, spec.screen, report.px_per_mm);
  report.width_mm = cells.width_mm();
  report.height_mm = cells.height_mm();
  report.cells = cells.cells();
  report.layout = {cells.tracks(), cells.cells_per_track(), spec.screen.cell_pitch_um(),
                   spec.screen.track_pitch_um(), spec.screen.stagger, spec.screen.cell_rate_hz,
                   spec.stylus_angle_deg};

  const CellGeometry geometry{spec.screen.cell_rate_hz, spec.screen.cell_pitch_um(), spec.stylus_angle_deg};
  SimStylusHeadOptions head_options = spec.head;
  head_options.cells = geometry;
  head_options.record_profile = true;
  head_options.record_sense = false;
  check_job_length(cells, spec.screen, report.px_per_mm, head_options.max_record_samples);
  SimStylusHead head(head_options);

  const ToolpathOptions toolpath_options{spec.setup, spec.screen.cell_rate_hz, 0};
  const std::vector<float> intended = intended_cut(cells, toolpath_options);
  report.samples = intended.size();
  const std::vector<CellFigures> intended_cells = measure_cells(intended, geometry);
  const std::vector<float> cell_depths = intended_cell_depths(cells, spec.setup);
  report.full_cell_depth_um = std::max(spec.setup.ct.full_cell_depth(1), spec.setup.lw.full_cell_depth(1));

  // The filters.
  report.filters = spec.filters;
  report.design_head = spec.nominal_head;
  switch (spec.filters) {
    case FilterChoice::nominal: report.bank = design_for_head(spec.nominal_head, spec.tuning.target); break;
    case FilterChoice::manual: report.bank = spec.manual_bank; break;
    case FilterChoice::off: break;
    case FilterChoice::tuned: {
      AutoTuneOptions tuning = spec.tuning;
      tuning.run.stop = spec.run.stop;
      tuning.run.virtual_time = spec.run.virtual_time;
      report.tuning = auto_tune(head, tuning);
      if (report.tuning->cancelled) {
        report.cancelled = true;
        return report;
      }
      report.bank = report.tuning->bank;
      report.design_head = report.tuning->fit.model;
      break;
    }
  }
  const FilterBank* bank = spec.filters == FilterChoice::off ? nullptr : &report.bank;

  report.filtered = engrave(cells, toolpath_options, bank, report.design_head, head, spec.run, intended,
                            intended_cells, cell_depths, &report.engraved_um);
  report.counts = report.filtered.counts;
  report.cancelled = report.filtered.run.cancelled;
  if (!report.cancelled && spec.compare_unfiltered && bank) {
    report.unfiltered = engrave(cells, toolpath_options, nullptr, report.design_head, head, spec.run, intended,
                                intended_cells, cell_depths, nullptr);
    report.cancelled = report.unfiltered->run.cancelled;
  }
  report.intended_um = intended;
  report.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return report;
}

}  // namespace mark
