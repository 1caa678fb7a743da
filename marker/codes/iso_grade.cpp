#include "marker/codes/iso_grade.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace mark {
namespace {

// A module as graded: its sampled grey and signed modulation (negative: on the wrong side of
// the threshold).
struct Cell {
  double grey = 0;
  double modulation = 0;
  bool wrong() const { return modulation < 0; }
  int grade() const { return wrong() ? 0 : modulation_grade(modulation); }
};

// Damage of a fixed-pattern segment: by its damaged modules' count (QR finders: ISO/IEC 18004)
// or share (ISO/IEC 16022's L, quiet zone and clock segments).
int damage_grade(int damaged, int modules, bool by_count) {
  if (by_count) return damaged == 0 ? 4 : damaged == 1 ? 3 : damaged == 2 ? 2 : damaged == 3 ? 1 : 0;
  const double share = modules ? static_cast<double>(damaged) / modules : 0;
  return damaged == 0 ? 4 : share <= 0.09 ? 3 : share <= 0.13 ? 2 : share <= 0.17 ? 1 : 0;
}

// The average grade of the segments, graded itself: 4 only when all are, then ≥ 3.5, 3, 2.5.
int average_grade(double mean) {
  return mean >= 4 - 1e-9 ? 4 : mean >= 3.5 ? 3 : mean >= 3.0 ? 2 : mean >= 2.5 ? 1 : 0;
}

// Isodata threshold: midway between the means of the samples below and above it.
double isodata(const std::vector<double>& v) {
  double t = std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(std::max<std::size_t>(1, v.size()));
  for (int i = 0; i < 50; ++i) {
    double lo = 0, hi = 0;
    int nlo = 0, nhi = 0;
    for (double x : v) (x < t ? (lo += x, ++nlo) : (hi += x, ++nhi));
    if (!nlo || !nhi) break;
    const double next = (lo / nlo + hi / nhi) / 2;
    if (std::abs(next - t) < 1e-6) break;
    t = next;
  }
  return t;
}

// Print growth along a track of modules that alternate dark and light (a clock track, a timing
// pattern): the mean width of the dark runs bounded by light on both sides, against one module.
std::optional<double> print_growth(const GreyImage& pic, const ModuleGrid& g, double threshold, int r0, int c0,
                                   int dr, int dc, int count) {
  constexpr int kPerModule = 40;
  std::vector<bool> dark;
  for (int i = 0; i <= count * kPerModule; ++i) {
    const double t = -0.5 + static_cast<double>(i) / kPerModule;
    dark.push_back(sample(pic, g.at(r0 + dr * t, c0 + dc * t)) < threshold);
  }
  double sum = 0;
  int runs = 0;
  for (std::size_t i = 1; i < dark.size();) {
    if (!(dark[i] && !dark[i - 1])) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < dark.size() && dark[j]) ++j;
    if (j < dark.size()) sum += static_cast<double>(j - i) / kPerModule, ++runs;
    i = j;
  }
  if (!runs) return std::nullopt;
  return sum / runs - 1;
}

}  // namespace

char grade_letter(int grade) { return "FDCBA"[std::clamp(grade, 0, 4)]; }

int parse_grade(char c) {
  switch (c) {
    case 'A': case 'a': return 4;
    case 'B': case 'b': return 3;
    case 'C': case 'c': return 2;
    case 'D': case 'd': return 1;
    case 'F': case 'f': return 0;
    default: return -1;
  }
}

int cell_contrast_grade(double cc) { return cc >= 0.30 ? 4 : cc >= 0.25 ? 3 : cc >= 0.20 ? 2 : cc >= 0.15 ? 1 : 0; }
int modulation_grade(double m) { return m >= 0.50 ? 4 : m >= 0.40 ? 3 : m >= 0.30 ? 2 : m >= 0.20 ? 1 : 0; }
int axial_nonuniformity_grade(double an) { return an <= 0.06 ? 4 : an <= 0.08 ? 3 : an <= 0.10 ? 2 : an <= 0.12 ? 1 : 0; }
int grid_nonuniformity_grade(double gn) { return gn <= 0.38 ? 4 : gn <= 0.50 ? 3 : gn <= 0.63 ? 2 : gn <= 0.75 ? 1 : 0; }
int unused_error_correction_grade(double u) { return u >= 0.62 ? 4 : u >= 0.50 ? 3 : u >= 0.37 ? 2 : u >= 0.25 ? 1 : 0; }

IsoGrade iso_grade(const GreyImage& pic, const ModuleMatrix& m, const SymbolMap& map, const ModuleGrid& grid,
                   bool decoded) {
  IsoGrade g;
  g.decode = decoded ? 4 : 0;
  g.module_x_px = grid.module_x_px();
  g.module_y_px = grid.module_y_px();
  // The symbol's modules sampled at their centres; the threshold between the two populations.
  std::vector<double> grey(static_cast<std::size_t>(m.rows) * m.cols);
  for (int r = 0; r < m.rows; ++r)
    for (int c = 0; c < m.cols; ++c) grey[static_cast<std::size_t>(r) * m.cols + c] = sample(pic, grid.at(r, c));
  g.global_threshold = isodata(grey);
  double light = 0, dark = 0;
  int nl = 0, nd = 0;
  for (int r = 0; r < m.rows; ++r)
    for (int c = 0; c < m.cols; ++c) (m.dark(r, c) ? (dark += grey[static_cast<std::size_t>(r) * m.cols + c], ++nd)
                                                   : (light += grey[static_cast<std::size_t>(r) * m.cols + c], ++nl));
  g.mean_light = nl ? light / nl : 0;
  g.mean_dark = nd ? dark / nd : 0;
  g.cell_contrast = g.mean_light > 0 ? std::max(0.0, (g.mean_light - g.mean_dark) / g.mean_light) : 0;
  g.cell_contrast_grade = cell_contrast_grade(g.cell_contrast);

  const double t = g.global_threshold;
  const auto cell = [&](int r, int c) {
    const bool inside = r >= 0 && r < m.rows && c >= 0 && c < m.cols;
    Cell k;
    k.grey = inside ? grey[static_cast<std::size_t>(r) * m.cols + c] : sample(pic, grid.at(r, c));
    const bool want_dark = inside && m.dark(r, c);
    const double span = want_dark ? t - g.mean_dark : g.mean_light - t;
    k.modulation = span > 0 ? (want_dark ? t - k.grey : k.grey - t) / span : -1;
    return k;
  };
  for (int r = 0; r < m.rows; ++r)
    for (int c = 0; c < m.cols; ++c) g.modules_wrong += cell(r, c).wrong();

  // Codewords: in error when any bit reads wrong; graded by their worst module.
  const int n = map.codewords();
  std::vector<int> cw_grade(static_cast<std::size_t>(n), 4);
  std::vector<char> cw_error(static_cast<std::size_t>(n), 0);
  std::vector<double> cw_mod(static_cast<std::size_t>(n), 1e9);
  for (int r = 0; r < m.rows; ++r)
    for (int c = 0; c < m.cols; ++c) {
      const int k = map.codeword_at(r, c);
      if (k < 0 || k >= n) continue;
      const Cell x = cell(r, c);
      cw_grade[static_cast<std::size_t>(k)] = std::min(cw_grade[static_cast<std::size_t>(k)], x.grade());
      cw_error[static_cast<std::size_t>(k)] |= x.wrong();
      cw_mod[static_cast<std::size_t>(k)] = std::min(cw_mod[static_cast<std::size_t>(k)], x.modulation);
    }
  g.codewords_wrong = static_cast<int>(std::count(cw_error.begin(), cw_error.end(), 1));
  // UEC with the codewords graded below `level` counted as erasures (level 0: none).
  const auto uec = [&](int level) {
    std::vector<int> errors(map.blocks.size(), 0), erasures(map.blocks.size(), 0);
    for (int k = 0; k < n; ++k) {
      const auto b = static_cast<std::size_t>(map.block_of[static_cast<std::size_t>(k)]);
      if (cw_error[static_cast<std::size_t>(k)]) ++errors[b];
      else if (cw_grade[static_cast<std::size_t>(k)] < level) ++erasures[b];
    }
    double worst = 1;
    for (std::size_t b = 0; b < map.blocks.size(); ++b) {
      const double budget = map.blocks[b].ec - map.blocks[b].protection;
      worst = std::min(worst, budget > 0 ? 1 - (erasures[b] + 2.0 * errors[b]) / budget : 0.0);
    }
    return std::max(0.0, worst);
  };
  g.unused_error_correction = decoded ? uec(0) : 0;  // no codeword graded below 0: no erasures
  g.unused_error_correction_grade = decoded ? unused_error_correction_grade(g.unused_error_correction) : 0;
  g.cell_modulation = 1e9;
  for (int k = 0; k < n; ++k)
    if (!cw_error[static_cast<std::size_t>(k)]) g.cell_modulation = std::min(g.cell_modulation, cw_mod[static_cast<std::size_t>(k)]);
  if (g.cell_modulation > 1e8) g.cell_modulation = 0;
  for (int level = 4; level >= 1 && decoded; --level)
    g.cell_modulation_grade = std::max(g.cell_modulation_grade, std::min(level, unused_error_correction_grade(uec(level))));

  // Fixed patterns: each segment's grade is the best level at which few enough of its modules
  // are wrong or graded below it; the symbol's is the lowest segment's and the average's.
  double sum = 0;
  int lowest = 4;
  for (const PatternSegment& s : map.segments) {
    SegmentGrade sg;
    sg.name = s.name;
    sg.modules = static_cast<int>(s.modules.size());
    std::vector<Cell> cells;
    for (const auto& [r, c] : s.modules) cells.push_back(cell(r, c));
    sg.damaged = static_cast<int>(std::count_if(cells.begin(), cells.end(), [](const Cell& x) { return x.wrong(); }));
    sg.grade = 0;
    for (int level = 4; level >= 1; --level) {
      const int below = static_cast<int>(std::count_if(cells.begin(), cells.end(), [&](const Cell& x) { return x.grade() < level; }));
      sg.grade = std::max(sg.grade, std::min(level, damage_grade(below, sg.modules, s.by_count)));
    }
    lowest = std::min(lowest, sg.grade);
    sum += sg.grade;
    g.segments.push_back(sg);
  }
  g.fixed_pattern_average = map.segments.empty() ? 4 : sum / static_cast<double>(map.segments.size());
  g.fixed_pattern_grade = std::min(lowest, average_grade(g.fixed_pattern_average));

  const double x = g.module_x_px, y = g.module_y_px;
  g.axial_nonuniformity = std::abs(x - y) / ((x + y) / 2);
  g.axial_nonuniformity_grade = axial_nonuniformity_grade(g.axial_nonuniformity);
  g.grid_nonuniformity = largest_local_shift_modules(pic, m, grid);
  g.grid_nonuniformity_grade = grid_nonuniformity_grade(g.grid_nonuniformity);

  // Print growth along the clock tracks (Data Matrix: top row, right column) or the timing
  // patterns (QR: row and column 6).
  if (m.symbology == Symbology::qr) {
    g.print_growth_x = print_growth(pic, grid, t, 6, 8, 0, 1, m.cols - 16);
    g.print_growth_y = print_growth(pic, grid, t, 8, 6, 1, 0, m.rows - 16);
  } else {
    g.print_growth_x = print_growth(pic, grid, t, 0, -1, 0, 1, m.cols + 1);
    g.print_growth_y = print_growth(pic, grid, t, -1, m.cols - 1, 1, 0, m.rows + 1);
  }

  g.overall = std::min({g.decode, g.cell_contrast_grade, g.cell_modulation_grade, g.fixed_pattern_grade,
                        g.axial_nonuniformity_grade, g.grid_nonuniformity_grade, g.unused_error_correction_grade});
  return g;
}

}  // namespace mark
