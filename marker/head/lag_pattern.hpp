#pragma once
// The lag test pattern: identification for a head that reports no position (an XY2-100 head
// is one-way), from a photograph or flatbed scan of what it marked. Straight lines are marked
// from rest at several speeds with every delay zero, on both axes and in both directions, the
// laser's power in proportion to the speed (the same energy per mm, so every line is as wide
// and its ends look alike whatever the speed).
//
// A first-order servo follows a ramp a lag v·τ behind the command; the laser goes off when the
// command reaches the line's end, so the mark stops v·τ short of it. The mark's far end of a
// forward and of a backward line on neighbouring rows lie L − 2·v·τ + c apart, where c (the
// spot's and the picture's blur at an end, and any small rotation of the picture) is the same for
// every speed: the slope of that distance over the speeds is −2τ, whatever the scale's offset.
// A second-order head follows a ramp 2ζ/ωn behind, so the fit gives its ramp lag.
//
// Right-angle corners, marked at speed without a stop, show what the lines cannot: a
// second-order head overshoots the corner (the axis that stops swings past it and back, the
// mark bulges outwards), a first-order head never does. The bulge's size and shape along the
// second leg give ζ at the lines' ramp lag (corner_fit.hpp).
//
// Layout (mm, field coordinates about `centre`): the x lines in rows `pitch` apart, forward
// (−x → +x) and backward in turn, slowest first; the y lines likewise in columns to the right,
// `gap` clear of the rows' ends. The corners in the space below the x rows (inside the lines'
// extent, so the marks' box is the same): per corner speed one corner turning from +x to +y
// (x overshoots) on the bottom row and one from +y to +x above it, `corner_leg` each leg.
#include <string>
#include <string_view>
#include <vector>

#include "driver/sim/head_model.hpp"
#include "driver/vec2.hpp"
#include "ringbuffer/scan_sample.hpp"

namespace mark {

struct LagLine {
  int axis = 0;            // 0: along x, 1: along y
  bool forward = true;     // towards +x / +y
  double speed_mm_s = 0;
  Vec2 start, end;         // as commanded
};

struct LagCorner {
  int axis = 0;            // the axis that stops at the corner: 0 runs +x then +y, 1 +y then +x
  double speed_mm_s = 0;
  Vec2 start, corner, end; // as commanded: lit from start through the corner to the end
};

struct LagPattern {
  std::string head;        // the head it was made for (its limits go into the fitted profile)
  double length_mm = 20;
  double pitch_mm = 1;
  double gap_mm = 3;
  std::vector<double> speeds_mm_s;
  std::vector<LagLine> lines;  // per axis, per speed: the forward line, then the backward one
  double corner_leg_mm = 0;    // 0: no corners (a pattern file written before they were added)
  std::vector<double> corner_speeds_mm_s;
  std::vector<LagCorner> corners;

  // The fastest line's speed: full laser power there, the others in proportion.
  double fastest_mm_s() const;
  // The commanded lines' extent (mm); the corners lie inside it.
  Vec2 min() const;
  Vec2 max() const;
};

// After a jump: long enough for the slowest plausible head (τ to ~0.6 ms) to come to rest far
// below a micrometre, as head_response.cpp's holds; after a line, for the beam to catch up with
// the laser off. The same on every device (samples or a board's dwells).
inline constexpr double kLagJumpSettle_s = 12e-3;
inline constexpr double kLagAfterLine_s = 2e-3;

// The pattern for this head: speeds 500, 1000, 2000, 3000, 4000 mm/s up to 40 % of its speed
// limit (at least three: slower ones are added below 500 for a slow head), centred on `centre`;
// corners with 4 mm legs at the speeds up to 2000 mm/s (at most three: the head settles on the
// second leg before its lagging end). Throws InputError when it does not fit in the head's field.
inline constexpr double kLagCornerLeg_mm = 4;
inline constexpr double kLagCornerTopSpeed_mm_s = 2000;
LagPattern lag_pattern(const HeadModel& head, Vec2 centre = {});

// The commands at `tick_s`: each line from rest (a jump, then a hold long enough for any head
// to settle), lit while the command runs along it at its speed with power speed / fastest, then
// a hold with the laser off; each corner likewise along both legs without a stop. Every sample
// lies inside the pattern's extent.
std::vector<ScanSample> lag_pattern_samples(const LagPattern& pattern, double tick_s);

// The pattern file (JSON, docs/speed.md): the lines as commanded, so the fit needs nothing
// else. parse throws InputError naming `where`, the key and the allowed range.
std::string lag_pattern_json(const LagPattern& pattern);
LagPattern parse_lag_pattern(std::string_view json_text, std::string_view where);
LagPattern load_lag_pattern(const std::string& path);

}  // namespace mark
