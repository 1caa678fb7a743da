#pragma once
// A production part as one picture. The simulated scanner marks each object of a part as a job
// of its own and clears its dose at each job's start, so the part's picture adds them up: every
// object's plan (one plan of all their commands, for the preview's jumps and blanking lines),
// the dose each left (DoseRaster::add) and their trace rows one after the other (device time
// running on from the object before). `mark --job --preview/--dose-png/--trace`, `job check
// --preview` and the station's GET /api/preview.png all draw it with the renderer of
// `marker mark --preview` (marker/preview/mark_preview.hpp).
#include <string>
#include <vector>

#include "driver/sim/dose_raster.hpp"
#include "driver/sim/sim_trace.hpp"
#include "marker/job/job.hpp"
#include "marker/plan/plan.hpp"
#include "marker/production/part_texts.hpp"

namespace mark {

class PartPicture {
 public:
  explicit PartPicture(double pixel_mm = 0.005) : dose_(pixel_mm) {}

  // One object marked: its plan, the dose and trace rows its job left on the scanner.
  void add(const Plan& plan, const DoseRaster& dose, const std::vector<SimTraceRow>& trace);

  const Plan& plan() const { return plan_; }
  const DoseRaster& dose() const { return dose_; }
  const std::vector<SimTraceRow>& trace() const { return trace_; }
  std::size_t objects() const { return objects_; }

 private:
  Plan plan_;
  DoseRaster dose_;
  std::vector<SimTraceRow> trace_;
  std::size_t objects_ = 0;
};

// The part with these texts as the planner draws it: every object laid out and planned for a
// sample-level device (each from where the one before it ends, as PartRunner plans them) and
// marked on a fresh simulated scanner of the job's head in virtual time. No device, no store:
// nothing is consumed. Throws InputError naming the object for a text the job cannot mark.
PartPicture simulate_part(const JobFile& job, const JobFonts& fonts, const std::vector<ObjectText>& texts);

// The dose picture's look (--dose-png): the response and part of the job's first object, on a
// dark part when any object marks an inverted code.
struct PartLookSpec {
  MarkResponse response;
  PartLook look;
  bool dark_part = false;
};
PartLookSpec part_look(const JobFile& job, const JobFonts& fonts);

}  // namespace mark
