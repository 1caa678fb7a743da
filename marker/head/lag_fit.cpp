#include "marker/head/lag_fit.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

#include "base/error.hpp"
#include "marker/head/pattern_marks.hpp"

namespace mark {
namespace {

// First and last index whose count reaches `min_count`; false when none does.
bool extent(const std::vector<int>& counts, int min_count, int& first, int& last) {
  first = -1;
  for (int i = 0; i < static_cast<int>(counts.size()); ++i)
    if (counts[static_cast<std::size_t>(i)] >= min_count) {
      if (first < 0) first = i;
      last = i;
    }
  return first >= 0;
}

struct Line {
  double slope = 0, intercept = 0;
};

Line fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
  const double d = n * sxx - sx * sx;
  Line l;
  l.slope = (n * sxy - sx * sy) / d;
  l.intercept = (sy - l.slope * sx) / n;
  return l;
}

}  // namespace

LagFit fit_lag_from_image(const GrayImage& g, double pixel_mm, const LagPattern& pattern,
                          const std::string& where) {
  if (g.width < 8 || g.height < 8)
    throw InputError("'" + where + "': the picture is too small to show the lag pattern");
  const PatternMarks marks(g);
  // Columns and rows holding at least 3 marked pixels: a speck of noise does not move the box.
  std::vector<int> cols(static_cast<std::size_t>(g.width)), rows(static_cast<std::size_t>(g.height));
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x)
      if (marks.ink(x, y) > 0) ++cols[static_cast<std::size_t>(x)], ++rows[static_cast<std::size_t>(y)];
  int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  if (!extent(cols, 3, x0, x1) || !extent(rows, 3, y0, y1))
    throw InputError("'" + where + "': no marks found");
  const Vec2 lo = pattern.min(), hi = pattern.max();
  const double seen_w = (x1 - x0 + 1) * pixel_mm, seen_h = (y1 - y0 + 1) * pixel_mm;
  const double want_w = hi.x - lo.x, want_h = hi.y - lo.y;
  if (std::abs(seen_w - want_w) > 0.05 * want_w || std::abs(seen_h - want_h) > 0.05 * want_h)
    throw InputError("'" + where + "': the marks span " + pattern_figure(seen_w) + " × " + pattern_figure(seen_h) +
                     " mm at " + pattern_figure(pixel_mm * 1e3) + " µm pixels, the pattern " + pattern_figure(want_w) +
                     " × " + pattern_figure(want_h) +
                     " mm (within 5 %): a wrong --pixel-um, or not a picture of this pattern");

  // Field mm ↔ picture pixels, placed by the box (its edges lie half a line's width outside the
  // commanded starts; a turned picture's box misplaces a line by up to a few tenths of a mm,
  // which the lines' own centres below take out).
  auto col_of = [&](double x) { return x0 + (x - lo.x) / pixel_mm; };
  auto row_of = [&](double y) { return y0 + (hi.y - y) / pixel_mm; };
  const int band = std::max(2, static_cast<int>(std::lround(std::min(0.3 * pattern.pitch_mm, 0.15) / pixel_mm)));
  const double margin_mm = std::min(1.0, pattern.gap_mm / 2);

  // Per axis: `along` is the pixel coordinate along that axis's lines (column for x lines),
  // `lateral` across them.
  struct Axis {
    int along_max = 0, lat_max = 0;
    std::function<double(double)> along_px, lateral_px;  // field mm → pixel coordinate
    std::function<double(int, int)> ink;                  // (along, lateral)
  };
  const Axis axes[2] = {
      {g.width - 1, g.height - 1, col_of, row_of, [&](int s, int k) { return marks.ink(s, k); }},
      {g.height - 1, g.width - 1, row_of, col_of, [&](int s, int k) { return marks.ink(k, s); }}};

  // Where each line's centre is, across it, at two places along its block (30 % and 70 % of the
  // length from the block's low end: every line is marked there whatever its direction, no lag
  // reaching back that far): the ink's runs across a five-pixel strip, the block's lines found
  // in order. A straight line through the two follows a picture turned by up to 1.5°.
  struct Track {
    double s1 = 0, c1 = 0, s2 = 0, c2 = 0;
    int lateral_at(int s) const {
      const double c = s2 == s1 ? c1 : c1 + (c2 - c1) * (s - s1) / (s2 - s1);  // both clamped to one edge
      return static_cast<int>(std::lround(c));
    }
  };
  std::vector<Track> tracks(pattern.lines.size());
  for (int a = 0; a < 2; ++a) {
    const Axis& ax = axes[a];
    std::vector<std::size_t> lines;  // this block's lines, in the order they lie across the picture
    double lat_lo = 1e300, lat_hi = -1e300, low = 1e300;
    for (std::size_t i = 0; i < pattern.lines.size(); ++i) {
      const LagLine& l = pattern.lines[i];
      if (l.axis != a) continue;
      lines.push_back(i);
      const double lat = a == 0 ? l.start.y : l.start.x;
      const double along = a == 0 ? std::min(l.start.x, l.end.x) : std::min(l.start.y, l.end.y);
      lat_lo = std::min(lat_lo, lat), lat_hi = std::max(lat_hi, lat), low = std::min(low, along);
    }
    auto lat_of = [&](std::size_t i) {
      return ax.lateral_px(a == 0 ? pattern.lines[i].start.y : pattern.lines[i].start.x);
    };
    std::sort(lines.begin(), lines.end(), [&](std::size_t p, std::size_t q) { return lat_of(p) < lat_of(q); });
    // The strip runs across the block and half a pitch beyond its outer lines.
    const double edge1 = ax.lateral_px(lat_lo - pattern.pitch_mm / 2);
    const double edge2 = ax.lateral_px(lat_hi + pattern.pitch_mm / 2);
    const int k_from = std::clamp(static_cast<int>(std::floor(std::min(edge1, edge2))), 0, ax.lat_max);
    const int k_to = std::clamp(static_cast<int>(std::ceil(std::max(edge1, edge2))), 0, ax.lat_max);
    for (int place = 0; place < 2; ++place) {
      const double s_px = std::clamp(ax.along_px(low + (place == 0 ? 0.3 : 0.7) * pattern.length_mm), 0.0,
                                     static_cast<double>(ax.along_max));
      const int s0 = static_cast<int>(std::lround(s_px));
      std::vector<double> profile(static_cast<std::size_t>(k_to - k_from + 1));
      for (int k = k_from; k <= k_to; ++k)
        for (int s = std::max(0, s0 - 2); s <= std::min(ax.along_max, s0 + 2); ++s)
          profile[static_cast<std::size_t>(k - k_from)] += std::max(0.0, ax.ink(s, k));
      // Runs of ink across the strip: (weight, centroid).
      std::vector<std::pair<double, double>> runs;
      for (std::size_t k = 0; k < profile.size();) {
        if (profile[k] <= 0) { ++k; continue; }
        double w = 0, wk = 0;
        for (; k < profile.size() && profile[k] > 0; ++k)
          w += profile[k], wk += profile[k] * static_cast<double>(k);
        runs.push_back({w, k_from + wk / w});
      }
      // A speck is not a line: runs under a tenth of the heaviest are dropped.
      double heaviest = 0;
      for (const auto& r : runs) heaviest = std::max(heaviest, r.first);
      std::erase_if(runs, [&](const auto& r) { return r.first < 0.1 * heaviest; });
      if (runs.size() != lines.size()) {
        std::ostringstream m;
        m << "'" << where << "': " << runs.size() << " " << (a == 0 ? "x" : "y")
          << " lines found across the picture "
          << (place == 0 ? 30 : 70) << " % along them, the pattern has " << lines.size()
          << ": not a picture of this pattern, or turned by more than 1.5°";
        throw InputError(m.str());
      }
      for (std::size_t j = 0; j < lines.size(); ++j) {
        Track& t = tracks[lines[j]];
        (place == 0 ? t.s1 : t.s2) = s_px;
        (place == 0 ? t.c1 : t.c2) = runs[j].second;
      }
    }
  }

  // The far end of a line, mm along its axis.
  auto far_end = [&](std::size_t index) {
    const LagLine& l = pattern.lines[index];
    const bool along_x = l.axis == 0;
    const Axis& ax = axes[l.axis];
    const Track& track = tracks[index];
    const double end = along_x ? l.end.x : l.end.y, start = along_x ? l.start.x : l.start.y;
    // Ink across the band about the line's centre at a position along the line.
    auto ink_at = [&](int s) {
      const int lat = track.lateral_at(s);
      double best = -1e9;
      for (int k = std::max(0, lat - band); k <= std::min(ax.lat_max, lat + band); ++k)
        best = std::max(best, ax.ink(s, k));
      return best;
    };
    // Pixel steps along the line in the direction of travel: +1 for +x; rows grow downwards.
    const double dir = l.forward ? 1 : -1;
    const int step = along_x ? (l.forward ? -1 : 1) : (l.forward ? 1 : -1);  // inwards, in pixels
    int s = std::clamp(static_cast<int>(std::lround(ax.along_px(end + dir * margin_mm))), 0, ax.along_max);
    const int stop = std::clamp(static_cast<int>(std::lround(ax.along_px((start + end) / 2))), 0, ax.along_max);
    double prev = ink_at(s);
    if (prev > 0) {
      std::ostringstream m;
      m << "'" << where << "': the " << (along_x ? "x" : "y") << " line at " << l.speed_mm_s
        << " mm/s is marked " << margin_mm << " mm past its end: not a picture of this pattern";
      throw InputError(m.str());
    }
    for (s += step; s != stop + step; s += step) {
      const double cur = ink_at(s);
      if (cur > 0) {
        const double frac = prev / (prev - cur);  // where the ink crosses 0 between s − step and s
        const double p = (s - step) + frac * step;
        return along_x ? lo.x + (p - x0) * pixel_mm : hi.y - (p - y0) * pixel_mm;
      }
      prev = cur;
    }
    std::ostringstream m;
    m << "'" << where << "': the " << (along_x ? "x" : "y") << " line at " << l.speed_mm_s
      << " mm/s has no mark within half its length of its end";
    throw InputError(m.str());
  };

  LagFit fit;
  double sum_sq = 0;
  for (int axis = 0; axis < 2; ++axis) {
    std::vector<double> v, d;
    std::vector<std::size_t> idx;
    for (std::size_t i = 0; i + 1 < pattern.lines.size(); ++i) {
      const LagLine& f = pattern.lines[i];
      const LagLine& b = pattern.lines[i + 1];
      if (f.axis != axis || !f.forward || b.forward || b.speed_mm_s != f.speed_mm_s) continue;
      LagPairFigure p;
      p.axis = axis;
      p.speed_mm_s = f.speed_mm_s;
      p.ends_apart_mm = far_end(i) - far_end(i + 1);
      v.push_back(p.speed_mm_s);
      d.push_back(p.ends_apart_mm);
      fit.pairs.push_back(p);
    }
    if (v.size() < 3) throw InputError("'" + where + "': the pattern has fewer than three speeds per axis");
    const Line line = fit_line(v, d);
    const double tau = -line.slope / 2;
    (axis == 0 ? fit.tau_x_s : fit.tau_y_s) = tau;
    for (LagPairFigure& p : fit.pairs)
      if (p.axis == axis) {
        p.residual_um = (p.ends_apart_mm - (line.intercept + line.slope * p.speed_mm_s)) * 1e3;
        sum_sq += p.residual_um * p.residual_um;
      }
    if (!(tau > 0)) {
      std::ostringstream m;
      m << "'" << where << "': the " << (axis == 0 ? "x" : "y") << " lines fit a lag of " << tau * 1e3
        << " ms, not above 0: the picture is mirrored or turned, or not of this pattern";
      throw InputError(m.str());
    }
  }
  fit.tau_s = (fit.tau_x_s + fit.tau_y_s) / 2;
  fit.rms_um = std::sqrt(sum_sq / static_cast<double>(fit.pairs.size()));

  // The lines' tilt in the picture (rows grow downwards): x lines' dY/dX, y lines' dX/dY.
  double turn[2] = {0, 0};
  int count[2] = {0, 0};
  for (std::size_t i = 0; i < pattern.lines.size(); ++i) {
    const Track& t = tracks[i];
    if (t.s2 == t.s1) continue;
    turn[pattern.lines[i].axis] += -(t.c2 - t.c1) / (t.s2 - t.s1);
    ++count[pattern.lines[i].axis];
  }
  const PlacedPicture placed{marks, pixel_mm, lo, hi, x0, y0, count[0] ? turn[0] / count[0] : 0,
                             count[1] ? turn[1] / count[1] : 0};
  fit.corners = fit_corners(placed, pattern, fit.tau_x_s, fit.tau_y_s, where);
  return fit;
}

HeadProfile picture_profile(HeadProfile p, const LagFit& fit) {
  const CornerFit& corners = fit.corners;
  p.model = corners.second_order ? ServoOrder::second : ServoOrder::first;
  p.tau_s = fit.tau_s;
  if (corners.second_order) p.omega_n_rad_s = corners.omega_n_rad_s, p.zeta = corners.zeta;
  p.fit_rms_first_um = corners.corners.empty() ? fit.rms_um : corners.rms_first_um;
  p.fit_rms_second_um = corners.corners.empty() ? 0 : corners.rms_second_um;
  p.resonance_hz = corners.ring.seen ? corners.ring.frequency_hz : 0;
  p.resonance_zeta = corners.ring.seen ? corners.ring.zeta : 0;
  p.source = "image";
  return p;
}

}  // namespace mark
