#pragma once
// What a mark was meant to be besides its strokes — the pen's energy per mm and the pulses its
// source fired along the real lit path — for the quality figures that compare the mark with it
// (quality.hpp: line continuity and dose sufficiency). The simulated scanner knows both for the
// job it ran (SimScanner::intent()).
#include <optional>

#include "driver/sim/pulse_train.hpp"

namespace mark {

struct MarkIntent {
  // The pen's nominal energy per mm: its power share / its marking speed, in the dose raster's
  // unit (seconds of full power per mm). A pen at 100 % and 1000 mm/s: 0.001. ≤ 0: the pen puts
  // nothing down, and no dose is sufficient.
  double nominal_dose_s_per_mm = 0;
  // The material's energy per mm, in the same unit: what a single line needs to mark one beam
  // diameter wide (mark_response.hpp), so the same for every pen. 0: not known.
  double material_dose_s_per_mm = 0;
  // Dose sufficiency judged against the material's energy per mm instead of the pen's own: a
  // fast pen whose power / speed is far below what the material needs is then not "high" however
  // evenly it puts that little down.
  bool dose_vs_material = false;
  // The pulse train along the lit path (the source's pulses, pulse_train.hpp). Unset for a
  // continuous-wave source: its line has no pulses to leave gaps between.
  std::optional<PulseFigures> pulses;
};

}  // namespace mark
