#pragma once
// Quality figures of a simulated mark against what was intended. The intended strokes come as
// polylines, one per lit stroke (a polyline whose last point equals its first is closed and has
// no ends); the reference samples every segment at its own step and weighs each sample by the
// length it stands for, so a line may come whole and a curve in short pieces (no coarser than
// the deviation the figures should see). Spatial grids make every query local,
// and a QualityReference prepares everything that depends only on the intended strokes once,
// so a speed search can evaluate many marks of the same strokes cheaply.
#include <cstddef>
#include <memory>
#include <vector>

#include "driver/sim/dose_raster.hpp"
#include "driver/sim/lit_paths.hpp"
#include "driver/sim/mark_intent.hpp"
#include "driver/vec2.hpp"

namespace mark {

struct QualityOptions {
  double coverage_radius_mm = 0.010;  // an intended point is covered if a lit path passes this close
  double dose_window_mm = 0.015;      // spot-sized window the dose is summed over
  double sample_step_mm = 0.005;      // spacing of the points sampled along the intended strokes
};

struct Quality {
  // Largest distance of a lit beam position from the intended stroke it is marking (each lit run
  // is measured against one stroke: the one nearest to most of its points).
  double max_deviation_um = 0;
  double rms_deviation_um = 0;   // RMS of that distance over the lit positions
  double coverage = 0;           // share of intended stroke length within coverage_radius of a lit path
  // Burn-in: the dose along the intended strokes divided by the dose an ideal constant-speed mark
  // of the same strokes would leave (so crossings and stroke ends, where the ideal is also
  // different, do not count), then max / median of that ratio. 1 = perfectly even; 1e9 when
  // more than half of the stroke length got no dose at all (the median is 0).
  double dose_ratio_max = 0;
  double overshoot_um = 0;       // furthest lit position beyond the end of an open stroke
  // Line continuity: the widest gap on the lit path's centre line between the spots of two
  // consecutive pulses of one lit run — pulse spacing − spot diameter, 0 when the spots touch
  // or overlap (and for a continuous-wave source). Each lit run starts its own train, so the
  // jumps between strokes, and between the dots of a dot-style code, are not gaps.
  double pulse_gap_max_um = 0;
  double spot_diameter_um = 0;   // the spots' diameter (0: no pulses were evaluated)
  // Dose sufficiency: the energy per mm the least-dosed stroke got (the median along it of the
  // dose over the ideal constant-speed mark's), as a share of the pen's nominal energy per mm
  // (MarkIntent), or of the material's when the intent says so (dose_vs_material). 1 = the pen's
  // power at its speed; power scaled with speed, or a stroke faster than the pen, shows below 1.
  // Strokes of no length (dwell dots) have no per-mm figure and do not count; with only those, 1.
  double dose_per_mm_fraction = 0;
  bool dose_vs_material = false;  // which reference dose_per_mm_fraction is a share of
  // The same least-dosed stroke as a share of the material's energy per mm (0: the material is
  // not known), whichever the class is judged on: how far a pen is from marking the material as
  // its reference line does.
  double material_dose_per_mm_fraction = 0;
  std::size_t lit_points = 0;    // lit positions evaluated (0: nothing was lit; coverage is 0)
};

// The intended strokes, indexed once: grids, sample points and the ideal dose at each.
class QualityReference {
 public:
  // pixel_mm must match the dose rasters evaluated later (SimScannerOptions::pixel_mm).
  explicit QualityReference(const std::vector<std::vector<Vec2>>& intended_polylines,
                            QualityOptions options = {}, double pixel_mm = 0.005);
  ~QualityReference();
  QualityReference(QualityReference&&) noexcept;
  QualityReference& operator=(QualityReference&&) noexcept;

  // Throws std::invalid_argument if the raster's pixel differs from the reference's.
  Quality evaluate(const LitPaths& lit, const DoseRaster& dose, const MarkIntent& intent) const;

 private:
  struct Data;
  std::unique_ptr<Data> data_;
};

// One-off evaluation: QualityReference(intended, options, dose.pixel_mm()).evaluate(lit, dose, intent).
Quality evaluate_quality(const std::vector<std::vector<Vec2>>& intended_polylines,
                         const LitPaths& lit, const DoseRaster& dose, const MarkIntent& intent,
                         QualityOptions options = {});

// The worse of two marks' figures, figure by figure (largest deviation, gap, ratio; smallest
// coverage, dose share, lit points): classify() of it is the lower class of the two. A part of
// several objects, or a pen that must hold on several plants, is as good as this.
Quality worse_of(const Quality& a, const Quality& b);

}  // namespace mark
