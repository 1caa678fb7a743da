#pragma once
// The cps workload in tests: the 62 characters A–Z a–z 0–9 in the built-in font at 1 mm cap
// height, centred on (0, 0.5), on SL10 (bench/prog_cps.cpp's layout), and SL10's profile as
// `marker head identify` fits it on the simulator — what cps plans with.
#include "driver/sim/sim_scanner.hpp"
#include "fonts/catalog.hpp"
#include "marker/head/head_fit.hpp"
#include "marker/job/job.hpp"
#include "marker/job/sim_evaluator.hpp"

namespace mark::test {

inline JobSpec cps_characters_spec() {
  JobSpec spec;
  spec.text = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  spec.font = open_font(kBuiltinFontName);
  spec.layout.height_mm = 1;
  spec.layout.align = Align::center;
  spec.layout.base = Point(0, 0.5);
  spec.head = head_sl10();
  return spec;
}

inline const HeadProfile& identified_sl10() {
  static const HeadProfile model = [] {
    SimScannerOptions o;
    o.head = head_sl10();
    return identify_head(o);
  }();
  return model;
}

// The job marked in virtual time on the simulator with `plant` for a head.
inline JobResult mark_on_plant(const JobSpec& spec, const Plant& plant) {
  JobOptions options;
  options.virtual_time = true;
  SimScannerOptions o = simulator_options(spec);
  o.plant = plant;
  SimScanner scanner(o);
  return run_job_simulated(spec, options, scanner);
}

}  // namespace mark::test
