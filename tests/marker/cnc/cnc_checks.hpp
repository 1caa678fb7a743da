#pragma once
// Test support: the geometric checks every CNC test applies to the moves LinuxCNC's rs274
// interpreted from a generated program, against the Figure the program was made from.
#include <gtest/gtest.h>

#include <string>
#include <tuple>

#include "marker/cnc/cut_settings.hpp"
#include "marker/cnc/gcode_options.hpp"
#include "marker/cnc/protrusion.hpp"
#include "marker/layout/figure.hpp"
#include "path_checks.hpp"
#include "rs274.hpp"
#include "test_figures.hpp"

namespace mark::test {

inline constexpr double kTolMm = 0.005;  // the bound for engraving moves vs strokes
// The strokes are flattened for fast distance queries: distances are overstated by at most this.
inline constexpr double kStrokeChordMm = 0.0002;
// What "closer than the tool radius" forgives: the flattening above plus rs274's printout.
inline constexpr double kClosenessTolMm = kStrokeChordMm + 0.0002;

enum class Variant { upright, mirrored, sheared };
const char* name(Dialect d);
const char* name(Fit f);
const char* name(Variant v);
inline void PrintTo(Fit f, std::ostream* os) { *os << name(f); }
inline void PrintTo(Variant v, std::ostream* os) { *os << name(v); }

// Every dialect × fitting × variant, as the rs274 suites run them, with readable test names.
using Case = std::tuple<Dialect, Fit, Variant>;
inline auto all_cases() {
  return ::testing::Combine(::testing::Values(Dialect::linuxcnc, Dialect::fanuc, Dialect::plain),
                            ::testing::Values(Fit::linear, Fit::inclined, Fit::circular),
                            ::testing::Values(Variant::upright, Variant::mirrored, Variant::sheared));
}
inline std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  return std::string(name(std::get<0>(info.param))) + "_" + name(std::get<1>(info.param)) + "_" +
         name(std::get<2>(info.param));
}

struct DepressionCheck {
  std::size_t cutting_moves = 0;
  std::size_t arcs = 0;
  double worst_off_stroke_mm = 0;
  double worst_uncovered_mm = 0;
};

// Every engraving move within kTolMm (+ the printout's resolution print_mm) of a stroke, every
// stroke within that of a full-depth move, sideways rapids only at safe height, full depth
// reached. Adds test failures itself and returns the figures.
DepressionCheck check_depression(const Figure& fig, const Rs274Run& run, const CutSettings& s, double print_mm);

struct ProtrusionCheck {
  double closest_to_letters_mm = 1e9;  // smallest distance of a tool-centre position from L
  double uncut_mm2 = 0;                // material left inside the plate, outside the letters
  int wider_than_tool = 0;             // places where a whole tool disc of material is left
};

ProtrusionCheck check_protrusion(const Figure& fig, const Rs274Run& run, const CutSettings& s,
                                 const ProtrusionResult& res);

}  // namespace mark::test

namespace mark {
// Dialect lives in mark, so GoogleTest finds its printer there.
inline void PrintTo(Dialect d, std::ostream* os) { *os << test::name(d); }
}  // namespace mark
