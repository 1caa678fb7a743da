#pragma once
// Where a symbol's modules are in a picture: an affine grid, module (row, col) centred at
// origin + col·col_step + row·row_step (picture pixels; rows down the symbol, columns along it).
// A verifier starts from where the code was meant to be (the placed code's frame) and fits the
// grid to the symbol's own pattern — the laser's lag or a misplaced part shift, stretch or turn
// it — by maximising the correlation of the sampled picture with the intended modules. The same
// fit on small tiles of the symbol gives the local deviations of grid non-uniformity.
#include <Eigen/Core>
#include <vector>

#include "base/grey_image.hpp"
#include "marker/codes/code_marks.hpp"
#include "marker/codes/module_matrix.hpp"

namespace mark {

struct ModuleGrid {
  Eigen::Vector2d origin{0, 0};    // centre of module (0, 0)
  Eigen::Vector2d col_step{1, 0};  // to the next column
  Eigen::Vector2d row_step{0, 1};  // to the next row

  Eigen::Vector2d at(double row, double col) const { return origin + col * col_step + row * row_step; }
  double module_x_px() const { return col_step.norm(); }
  double module_y_px() const { return row_step.norm(); }
};

// The grid where the code was meant to be, in the picture's pixels.
ModuleGrid intended_grid(const PlacedCode& code, const GreyImage& picture);

// The picture at a fractional pixel position (bilinear; the edge pixels beyond the picture).
double sample(const GreyImage& picture, const Eigen::Vector2d& at);

// The intended modules a fit compares with: the symbol and `quiet` modules of its quiet zone
// around it (light), as (row, col, dark).
struct ModuleRef {
  int row, col;
  bool dark;
};
std::vector<ModuleRef> module_refs(const ModuleMatrix& matrix, int quiet);

// The grid fitted to the picture from `start`: translation, the two steps' lengths and angles,
// within half a module of the start and 10 % of its scale. Correlation of the samples at the
// module centres with the intended pattern, maximised by a shrinking pattern search.
ModuleGrid fit_grid(const GreyImage& picture, const std::vector<ModuleRef>& modules, const ModuleGrid& start);

// Local deviation of the symbol from a fitted grid: for each tile of `tile` × `tile` modules
// that holds edges both ways, the shift that best fits its modules (to 1/32 module, within half
// a module); the largest over all tiles, in modules. 0 when no tile qualifies.
double largest_local_shift_modules(const GreyImage& picture, const ModuleMatrix& matrix, const ModuleGrid& grid,
                                   int tile = 4);

// Correlation of the picture at `side` × `side` points across each module with the intended
// pattern (−1 .. 1).
double pattern_correlation(const GreyImage& picture, const std::vector<ModuleRef>& modules, const ModuleGrid& grid,
                           int side = 4);

}  // namespace mark
