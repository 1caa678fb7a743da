#include "marker/codes/module_grid.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace mark {

ModuleGrid intended_grid(const PlacedCode& code, const GreyImage& picture) {
  const auto pixel = [&](int row, int col) {
    const Point field = code.to_field * code.module_box(row, col).center();
    return Eigen::Vector2d(picture.column_of(field.x()), picture.row_of(field.y()));
  };
  ModuleGrid g;
  g.origin = pixel(0, 0);
  g.col_step = pixel(0, 1) - g.origin;
  g.row_step = code.matrix.rows > 1 ? Eigen::Vector2d(pixel(1, 0) - g.origin) : Eigen::Vector2d(-g.col_step.y(), g.col_step.x());
  return g;
}

double sample(const GreyImage& p, const Eigen::Vector2d& at) {
  const double x = std::clamp(at.x(), 0.0, p.width - 1.0), y = std::clamp(at.y(), 0.0, p.height - 1.0);
  const int x0 = std::min(static_cast<int>(x), p.width - 2 < 0 ? 0 : p.width - 2);
  const int y0 = std::min(static_cast<int>(y), p.height - 2 < 0 ? 0 : p.height - 2);
  const int x1 = std::min(x0 + 1, p.width - 1), y1 = std::min(y0 + 1, p.height - 1);
  const double fx = x - x0, fy = y - y0;
  return (1 - fy) * ((1 - fx) * p.at(x0, y0) + fx * p.at(x1, y0)) + fy * ((1 - fx) * p.at(x0, y1) + fx * p.at(x1, y1));
}

std::vector<ModuleRef> module_refs(const ModuleMatrix& m, int quiet) {
  std::vector<ModuleRef> out;
  const int qr = m.rows > 1 ? quiet : 0;
  for (int r = -qr; r < m.rows + qr; ++r)
    for (int c = -quiet; c < m.cols + quiet; ++c) {
      const bool inside = r >= 0 && r < m.rows && c >= 0 && c < m.cols;
      out.push_back({r, c, inside && m.dark(r, c)});
    }
  return out;
}

double pattern_correlation(const GreyImage& picture, const std::vector<ModuleRef>& modules, const ModuleGrid& g,
                           int kSide) {
  // Pearson correlation of the picture with the intended pattern ("light" 1, dark 0), sampled
  // at kSide × kSide points across each module: the module's middle alone sits on a plateau of
  // the aperture's picture and cannot feel where its edges are.
  double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0, n = 0;
  for (const ModuleRef& m : modules) {
    const double y = m.dark ? 0.0 : 1.0;
    for (int i = 0; i < kSide; ++i)
      for (int j = 0; j < kSide; ++j) {
        const double x = sample(picture, g.at(m.row + (i + 0.5) / kSide - 0.5, m.col + (j + 0.5) / kSide - 0.5));
        sx += x, sy += y, sxx += x * x, syy += y * y, sxy += x * y, n += 1;
      }
  }
  if (n == 0) return 0;
  const double cov = sxy - sx * sy / n, vx = sxx - sx * sx / n, vy = syy - sy * sy / n;
  return vx > 0 && vy > 0 ? cov / std::sqrt(vx * vy) : 0;
}

namespace {

// The grid for parameters p = (dx, dy, ln sx, ln sy, θx, θy) applied to `start`: each step
// scaled and turned on its own (which covers stretch, rotation and shear), about the symbol's
// middle, then shifted.
ModuleGrid apply(const ModuleGrid& s, const std::array<double, 6>& p, const Eigen::Vector2d& middle_rc) {
  const auto turn = [](const Eigen::Vector2d& v, double a) {
    return Eigen::Vector2d(std::cos(a) * v.x() - std::sin(a) * v.y(), std::sin(a) * v.x() + std::cos(a) * v.y());
  };
  ModuleGrid g;
  g.col_step = turn(s.col_step, p[4]) * std::exp(p[2]);
  g.row_step = turn(s.row_step, p[5]) * std::exp(p[3]);
  const Eigen::Vector2d middle = s.at(middle_rc.x(), middle_rc.y());
  g.origin = middle - middle_rc.y() * g.col_step - middle_rc.x() * g.row_step + Eigen::Vector2d(p[0], p[1]);
  return g;
}

}  // namespace

ModuleGrid fit_grid(const GreyImage& picture, const std::vector<ModuleRef>& modules, const ModuleGrid& start) {
  if (modules.empty()) return start;
  int rows = 0, cols = 0;
  for (const ModuleRef& m : modules) rows = std::max(rows, m.row), cols = std::max(cols, m.col);
  const Eigen::Vector2d middle(rows / 2.0, cols / 2.0);
  const double x = start.module_x_px();
  // A large symbol pins its grid with fewer points a module (its edges are many).
  const int side = modules.size() > 2000 ? 2 : 4;
  const auto score = [&](const ModuleGrid& g) { return pattern_correlation(picture, modules, g, side); };
  // Steps: a quarter module of shift, 2 % of scale, a degree; limits: half a module, 10 %, 5°.
  std::array<double, 6> p{}, step{x / 4, x / 4, 0.02, 0.02, 0.0175, 0.0175};
  const std::array<double, 6> limit{x / 2, x / 2, 0.1, 0.1, 0.0873, 0.0873};
  double best = score(start);
  for (int round = 0; round < 12; ++round) {
    bool improved = true;
    while (improved) {
      improved = false;
      for (std::size_t k = 0; k < p.size(); ++k)
        for (double sign : {1.0, -1.0}) {
          std::array<double, 6> q = p;
          q[k] += sign * step[k];
          if (std::abs(q[k]) > limit[k]) continue;
          const double c = score(apply(start, q, middle));
          if (c > best + 1e-12) best = c, p = q, improved = true;
        }
    }
    for (double& s : step) s /= 2;
  }
  return apply(start, p, middle);
}

double largest_local_shift_modules(const GreyImage& picture, const ModuleMatrix& m, const ModuleGrid& g, int tile) {
  const double x = (g.module_x_px() + g.module_y_px()) / 2;
  double largest = 0;
  for (int r0 = 0; r0 < m.rows; r0 += tile)
    for (int c0 = 0; c0 < m.cols; c0 += tile) {
      // The tile with a module of context around it (inside the symbol or its quiet zone).
      std::vector<ModuleRef> refs;
      int edges_h = 0, edges_v = 0;
      for (int r = r0 - 1; r <= std::min(m.rows, r0 + tile); ++r)
        for (int c = c0 - 1; c <= std::min(m.cols, c0 + tile); ++c) {
          const auto dark = [&](int rr, int cc) { return rr >= 0 && rr < m.rows && cc >= 0 && cc < m.cols && m.dark(rr, cc); };
          refs.push_back({r, c, dark(r, c)});
          edges_h += dark(r, c) != dark(r, c + 1);
          edges_v += dark(r, c) != dark(r + 1, c);
        }
      if (edges_h < 2 || edges_v < 2) continue;  // nothing to pin the tile along one axis
      // Shifts within half a module: on a lattice of 1/8 module, then of 1/32 about the best;
      // the smallest of equal fits.
      Eigen::Vector2d best_at(0, 0);
      for (const double step : {0.125, 0.03125}) {
        const Eigen::Vector2d around = best_at;
        double best = -2, best_shift = 1e9;
        for (int i = -4; i <= 4; ++i)
          for (int j = -4; j <= 4; ++j) {
            const Eigen::Vector2d at = around + Eigen::Vector2d(i, j) * step;
            if (at.norm() > 0.5 + 1e-9) continue;
            ModuleGrid t = g;
            t.origin += at * x;
            const double c = pattern_correlation(picture, refs, t);
            if (c > best + 1e-9 || (c > best - 1e-9 && at.norm() < best_shift)) best = c, best_shift = at.norm(), best_at = at;
          }
      }
      largest = std::max(largest, best_at.norm());
    }
  return largest;
}

}  // namespace mark
