#pragma once
// A gravure job from image to engraved cylinder on the simulated head:
//
//   image (+ LW mask) ─► cells ─► control points ─► spline ─► 200 kHz toolpath
//     ─► notch / emphasis biquads ─► LineMemory<StylusSample> ─► Drain ─► SimStylusHead
//
// with the filters chosen four ways: designed for the head's nameplate model (the default),
// designed from the head measured by the automatic tuning, typed in by hand (notches and an
// emphasis, FIG. 12), or off. The same job is then engraved once more without filters (the
// comparison the seed's FIG. 9–11 make), and both cut profiles are measured against the
// intended one — the toolpath's curve — and cell by cell against the depths the image's grey
// levels asked for (engraving_compare.hpp).
#include <optional>
#include <string>
#include <vector>

#include "driver/sim/sim_stylus_head.hpp"
#include "marker/gravure/auto_tune.hpp"
#include "marker/gravure/cell_setup.hpp"
#include "marker/gravure/engraving_compare.hpp"
#include "marker/gravure/gravure_preview.hpp"
#include "marker/gravure/screen.hpp"
#include "marker/gravure/stylus_run.hpp"
#include "marker/image/gray_image.hpp"

namespace mark {

enum class FilterChoice { nominal, tuned, manual, off };
std::string_view to_string(FilterChoice choice);

struct GravureJobSpec {
  GrayImage image;
  std::optional<GrayImage> mask;          // line-work where dark
  GravureScreen screen;
  double px_per_mm = 0;                   // 0: four pixels a cell along the track
  GravureSetup setup;
  double stylus_angle_deg = 120;
  SimStylusHeadOptions head;              // the simulated head (its true resonances)
  FilterChoice filters = FilterChoice::nominal;
  StylusHeadModel nominal_head = default_stylus_head();  // what `nominal` designs for
  FilterBank manual_bank;                 // for `manual`
  AutoTuneOptions tuning;                 // for `tuned`
  bool compare_unfiltered = true;
  StylusRunOptions run;
};

struct EngravingResult {
  StylusRunResult run;
  DepthError depth_error;            // cut profile against the toolpath's curve
  CellError cell_error;              // cell figures against the toolpath's curve's
  DepthError depth_error_vs_cells;   // each cell's deepest cut against the depth its grey level asked for
  double drive_peak_um = 0;
  double max_cut_um = 0;
  double advance_samples = 0;
  CellCounts counts;  // kinds of the cells planned
};

struct GravureReport {
  GravureLayout layout;
  double width_mm = 0, height_mm = 0, px_per_mm = 0;
  std::uint64_t cells = 0;
  std::uint64_t samples = 0;
  CellCounts counts;
  FilterChoice filters = FilterChoice::nominal;
  FilterBank bank;                           // the filters the job ran with (empty when off)
  StylusHeadModel design_head;               // the head model the bank was designed for
  std::optional<AutoTuneResult> tuning;
  EngravingResult filtered;                  // the job as engraved (with `bank`)
  std::optional<EngravingResult> unfiltered; // the comparison run
  std::vector<float> intended_um, engraved_um;  // cut profiles, for the preview
  double full_cell_depth_um = 0;             // the deepest cell the setup can ask for (CT or LW)
  bool cancelled = false;
  double wall_time_s = 0;
};

// Throws InputError for a bad spec or a failed fit, DeviceFaultError when the head faults.
GravureReport run_gravure_job(const GravureJobSpec& spec);

}  // namespace mark
