#pragma once
// Print quality of a 2-D symbol as a DPM verifier grades it, after ISO/IEC TR 29158
// (AIM DPM-1-2006), on the picture through the synthetic aperture, against the symbol's own
// grid fitted to the picture and against the modules that were meant (which a verifier knows
// once the symbol has decoded):
//
//   cell contrast CC = (ML − MD) / ML       means of the light and the dark modules' centres
//   cell modulation CM                      per module (R − GT)/(ML − GT) or (GT − R)/(GT − MD),
//                                           graded per codeword and weighed against the
//                                           error correction left (ISO/IEC 15415's method)
//   fixed pattern damage FPD                each segment's damaged modules, and their average
//   axial non-uniformity AN                 |X − Y| / mean of the fitted grid's module pitches
//   grid non-uniformity GN                  largest local shift of the symbol off that grid, modules
//   unused error correction UEC             1 − (e + 2t)/(d − p) of the worst block
//   print growth (reported, not graded)     dark modules' width along the clock / timing tracks
//
// Grades are 4 (A) … 0 (F); the overall grade is the lowest of decode, CC, CM, FPD, AN, GN and
// UEC. docs/codes.md gives every threshold and what it rests on.
#include <optional>
#include <string>
#include <vector>

#include "base/grey_image.hpp"
#include "marker/codes/module_grid.hpp"
#include "marker/codes/module_matrix.hpp"
#include "marker/codes/symbol_map.hpp"

namespace mark {

struct SegmentGrade {
  std::string name;
  int damaged = 0;  // modules on the wrong side of the threshold
  int modules = 0;
  int grade = 4;
};

struct IsoGrade {
  int overall = 0;
  int decode = 0;
  double mean_light = 0, mean_dark = 0;  // grey levels of the light and dark module centres
  double global_threshold = 0;           // grey
  double cell_contrast = 0;              // fraction
  int cell_contrast_grade = 0;
  double cell_modulation = 0;            // the lowest codeword's modulation, fraction
  int cell_modulation_grade = 0;
  int fixed_pattern_grade = 0;
  double fixed_pattern_average = 0;      // mean of the segment grades
  std::vector<SegmentGrade> segments;
  double axial_nonuniformity = 0;        // fraction
  int axial_nonuniformity_grade = 0;
  double grid_nonuniformity = 0;         // modules
  int grid_nonuniformity_grade = 0;
  double unused_error_correction = 0;    // fraction, the worst block
  int unused_error_correction_grade = 0;
  int codewords_wrong = 0;
  std::optional<double> print_growth_x, print_growth_y;  // (dark width − module) / module
  std::size_t modules_wrong = 0;         // symbol modules on the wrong side of the threshold
  double module_x_px = 0, module_y_px = 0;  // the fitted grid's pitch
  double aperture_modules = 0;           // the synthetic aperture it was graded through
};

// Grades the symbol `matrix` seen in `aperture_picture` (the camera's picture through the
// synthetic aperture) on `grid` (fitted). `decoded`: the readers decoded it exactly.
IsoGrade iso_grade(const GreyImage& aperture_picture, const ModuleMatrix& matrix, const SymbolMap& map,
                   const ModuleGrid& grid, bool decoded);

// Grade letters: 4 A, 3 B, 2 C, 1 D, 0 F.
char grade_letter(int grade);
// 'A'..'D', 'F' (either case) → 4..0; −1 for anything else.
int parse_grade(char letter);

// The threshold grades, each from the standard's table: CC ≥ 30/25/20/15 %, modulation
// ≥ 50/40/30/20 %, AN ≤ 6/8/10/12 %, GN ≤ 0.38/0.50/0.63/0.75 module, UEC ≥ 62/50/37/25 %.
int cell_contrast_grade(double cc);
int modulation_grade(double modulation);
int axial_nonuniformity_grade(double an);
int grid_nonuniformity_grade(double gn_modules);
int unused_error_correction_grade(double uec);

}  // namespace mark
