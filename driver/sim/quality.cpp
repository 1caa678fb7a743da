#include "driver/sim/quality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>

#include "driver/sim/segment_grid.hpp"

namespace mark {
namespace {

constexpr double fine_cell_mm = 0.025;
constexpr int fine_rings = static_cast<int>(1.0 / fine_cell_mm);  // 1 mm; beyond, the coarse grid
constexpr double coarse_cell_mm = 1.0;
constexpr double no_median_ratio = 1e9;  // reported when most of the strokes got no dose

// A point every ≤ step along the intended strokes (midpoints of equal pieces of each segment),
// its share of the stroke length, and its stroke. Not stored: a long text has millions (a point
// every 2 µm of its strokes), and each is computed again from its segment when it is read.
struct StrokeSample {
  Vec2 p;
  double weight;
  std::uint32_t stroke;
};

// A value read at a sample, and the stroke length that sample stands for.
struct Weighted {
  double value;
  double weight;
};

// The median along the strokes' length: the smallest value with at least half the total weight at
// or below it. Weighted by length, not counted by point, so a caller that cuts a curve finer than
// the line beside it does not tip it. Equal weights when the total is 0 (only dots). Expected
// linear time: nth_element halves the range that still holds the median.
double length_median(std::vector<Weighted> v) {
  if (v.empty()) return 0;
  double total = 0;
  for (const Weighted& w : v) total += w.weight;
  if (!(total > 0)) {
    for (Weighted& w : v) w.weight = 1;
    total = static_cast<double>(v.size());
  }
  const auto by_value = [](const Weighted& a, const Weighted& b) { return a.value < b.value; };
  double need = 0.5 * total;  // weight still to pass within [lo, hi)
  auto lo = v.begin(), hi = v.end();
  while (hi - lo > 1) {
    const auto mid = lo + (hi - lo) / 2;
    std::nth_element(lo, mid, hi, by_value);
    double below = 0;
    for (auto it = lo; it != mid; ++it) below += it->weight;
    if (below >= need) {
      hi = mid;
    } else if (below + mid->weight >= need) {
      return mid->value;
    } else {
      need -= below + mid->weight;
      lo = mid + 1;
    }
  }
  return lo->value;
}

}  // namespace

struct QualityReference::Data {
  QualityOptions options;
  double pixel_mm;
  std::shared_ptr<const std::vector<Segment>> shared_segments;  // with the grids
  std::span<const Segment> segments;                            // *shared_segments
  // Nested, not in the anonymous namespace: Data has linkage, and a unity build would warn
  // (-Wsubobject-linkage) about a member whose type has none.
  struct Stroke {
    std::uint32_t first_segment;
    std::uint32_t last_segment;
    bool closed;
  };
  std::vector<Stroke> strokes;
  std::vector<std::uint32_t> stroke_of_segment;
  // Index of each segment's first sample (one entry more than segments: the count at the end),
  // and the dose an ideal constant-speed mark leaves in the window around each sample.
  std::vector<std::size_t> first_sample;
  std::vector<double> ideal_dose;

  std::size_t sample_count() const { return first_sample.empty() ? 0 : first_sample.back(); }
  static int pieces_of(const Segment& seg, double step) {
    return std::max(1, static_cast<int>(std::ceil(norm(seg.b - seg.a) / step)));
  }
  // f(index, sample) for every sample of segment j, in order.
  template <class F>
  void for_each_sample_of(std::size_t j, F&& f) const {
    const Segment& seg = segments[j];
    const double len = norm(seg.b - seg.a);
    const int pieces = pieces_of(seg, options.sample_step_mm);
    for (int k = 0; k < pieces; ++k)
      f(first_sample[j] + static_cast<std::size_t>(k),
        StrokeSample{seg.a + ((k + 0.5) / pieces) * (seg.b - seg.a), len / pieces, stroke_of_segment[j]});
  }
  template <class F>
  void for_each_sample(F&& f) const {
    for (std::size_t j = 0; j < segments.size(); ++j) for_each_sample_of(j, f);
  }
  SegmentGrid fine{std::vector<Segment>{}, fine_cell_mm};
  SegmentGrid coarse{std::vector<Segment>{}, coarse_cell_mm};

  void collect(const std::vector<std::vector<Vec2>>& polylines) {
    // Sized once: growing by doubling held up to 1.5 copies at the last growth.
    std::size_t n_segments = 0;
    for (const auto& line : polylines)
      if (!line.empty()) n_segments += std::max<std::size_t>(line.size(), 2) - 1;
    std::vector<Segment> built;
    built.reserve(n_segments);
    stroke_of_segment.reserve(n_segments);
    first_sample.reserve(n_segments + 1);
    first_sample.push_back(0);
    for (const auto& line : polylines) {
      if (line.empty()) continue;
      const auto first = static_cast<std::uint32_t>(built.size());
      const auto stroke = static_cast<std::uint32_t>(strokes.size());
      // A single point is a dot: one zero-length segment.
      const std::size_t n = std::max<std::size_t>(line.size(), 2);
      for (std::size_t i = 1; i < n; ++i) {
        const Vec2 a = line[std::min(i - 1, line.size() - 1)], b = line[std::min(i, line.size() - 1)];
        built.push_back({a, b});
        stroke_of_segment.push_back(stroke);
        first_sample.push_back(first_sample.back() + static_cast<std::size_t>(pieces_of(built.back(), options.sample_step_mm)));
      }
      const bool closed = line.size() > 2 && norm(line.front() - line.back()) < 1e-9;
      strokes.push_back({first, static_cast<std::uint32_t>(built.size() - 1), closed});
    }
    ideal_dose.assign(sample_count(), 0.0);
    shared_segments = std::make_shared<const std::vector<Segment>>(std::move(built));
    segments = *shared_segments;
  }

  // The ideal dose is laid down and read a band of kIdealBand_mm at a time, each band's raster
  // holding every segment that reaches a pixel its samples read (the disc plus the deposit's
  // bilinear spread), deposited in index order: each pixel sums the same deposits in the same
  // order as a raster of the whole job would, so the figures are the same to the bit, and memory
  // is one band's instead of a second raster as large as the simulator's.
  void prepare_ideal_dose() {
    if (segments.empty()) return;
    constexpr double kIdealBand_mm = 2;
    const double reach = options.dose_window_mm + 3 * pixel_mm;
    double y0 = std::numeric_limits<double>::infinity(), y1 = -y0;
    for_each_sample([&](std::size_t, const StrokeSample& s) { y0 = std::min(y0, s.p.y), y1 = std::max(y1, s.p.y); });
    const auto band_of = [&](double y) {
      return static_cast<std::size_t>(std::clamp(std::floor((y - y0) / kIdealBand_mm), 0.0, std::floor((y1 - y0) / kIdealBand_mm)));
    };
    const std::size_t bands = band_of(y1) + 1;
    // Per band: the segments with a sample in it (each sample is read in its own band only),
    // and the segments whose dose reaches it.
    std::vector<std::vector<std::uint32_t>> band_sampled(bands), band_segments(bands);
    for (std::size_t j = 0; j < segments.size(); ++j) {
      std::size_t last = bands;
      for_each_sample_of(j, [&](std::size_t, const StrokeSample& s) {
        if (const std::size_t b = band_of(s.p.y); b != last) {
          if (band_sampled[b].empty() || band_sampled[b].back() != j) band_sampled[b].push_back(static_cast<std::uint32_t>(j));
          last = b;
        }
      });
      const Segment& seg = segments[j];
      const double lo = std::min(seg.a.y, seg.b.y) - reach, hi = std::max(seg.a.y, seg.b.y) + reach;
      if (hi < y0 || lo > y1) continue;
      for (std::size_t b = band_of(lo); b <= band_of(hi); ++b) band_segments[b].push_back(static_cast<std::uint32_t>(j));
    }
    for (std::size_t b = 0; b < bands; ++b) {
      if (band_sampled[b].empty()) continue;
      DoseRaster ideal(pixel_mm);
      for (const std::uint32_t j : band_segments[b])
        ideal.deposit_segment(segments[j].a, segments[j].b, std::max(norm(segments[j].b - segments[j].a), 1e-9));
      for (const std::uint32_t j : band_sampled[b])
        for_each_sample_of(j, [&](std::size_t i, const StrokeSample& s) {
          if (band_of(s.p.y) == b) ideal_dose[i] = ideal.sum_disc(s.p, options.dose_window_mm);
        });
      std::vector<std::uint32_t>().swap(band_segments[b]);  // a band's lists are not needed again
      std::vector<std::uint32_t>().swap(band_sampled[b]);
    }
  }

  // Nearest intended segment to p, of any stroke, or only of stroke `only` when given.
  SegmentGrid::Nearest nearest(Vec2 p, std::optional<std::uint32_t> only = std::nullopt) const {
    std::uint32_t first = 0, last = std::numeric_limits<std::uint32_t>::max();
    if (only) first = strokes[*only].first_segment, last = strokes[*only].last_segment;
    SegmentGrid::Nearest n = fine.nearest(p, fine_rings, first, last);
    if (std::isinf(n.distance)) n = coarse.nearest(p, 1 << 20, first, last);
    return n;
  }

  // The stroke a lit run marks: the one nearest to most of its points (ties: the lower index).
  std::uint32_t stroke_marked_by(const std::vector<SegmentGrid::Nearest>& nearest_any,
                                 std::vector<std::uint32_t>& ids) const {
    ids.clear();
    for (const SegmentGrid::Nearest& n : nearest_any) ids.push_back(stroke_of_segment[n.segment]);
    std::sort(ids.begin(), ids.end());
    std::uint32_t best = ids.front();
    std::size_t best_count = 0;
    for (std::size_t i = 0, j = 0; i < ids.size(); i = j) {
      while (j < ids.size() && ids[j] == ids[i]) ++j;
      if (j - i > best_count) best = ids[i], best_count = j - i;
    }
    return best;
  }

  // How far a lit point lies beyond the end of an open stroke, along the stroke's end direction.
  double overshoot_mm(const SegmentGrid::Nearest& n) const {
    const Stroke& s = strokes[stroke_of_segment[n.segment]];
    if (s.closed) return 0;
    const Segment& seg = segments[n.segment];
    const double len = norm(seg.b - seg.a);
    double beyond = 0;
    if (n.segment == s.first_segment && n.t < 0) beyond = std::max(beyond, -n.t * len);
    if (n.segment == s.last_segment && n.t > 1) beyond = std::max(beyond, (n.t - 1) * len);
    return beyond;
  }
};

QualityReference::QualityReference(const std::vector<std::vector<Vec2>>& intended_polylines,
                                   QualityOptions options, double pixel_mm)
    : data_(std::make_unique<Data>()) {
  Data& d = *data_;
  d.options = options;
  d.pixel_mm = pixel_mm;
  d.collect(intended_polylines);
  d.fine = SegmentGrid(d.shared_segments, fine_cell_mm);
  d.coarse = SegmentGrid(d.shared_segments, coarse_cell_mm);
  d.prepare_ideal_dose();
}

QualityReference::~QualityReference() = default;
QualityReference::QualityReference(QualityReference&&) noexcept = default;
QualityReference& QualityReference::operator=(QualityReference&&) noexcept = default;

Quality QualityReference::evaluate(const LitPaths& lit, const DoseRaster& dose, const MarkIntent& intent) const {
  const Data& d = *data_;
  if (std::abs(dose.pixel_mm() - d.pixel_mm) > 1e-12)
    throw std::invalid_argument("quality: dose raster pixel differs from the reference's");
  Quality q;
  if (d.sample_count() == 0) return q;

  // Deviation and overshoot of every lit position, measured against the stroke its lit run
  // marks: a beam that cuts across to a neighbouring stroke is off its own stroke, however close
  // it passes to another.
  double sum_sq = 0, worst = 0, overshoot = 0;
  std::vector<SegmentGrid::Nearest> nearest_any;
  std::vector<std::uint32_t> ids;
  for (const auto& run : lit.runs) {
    if (run.empty()) continue;
    nearest_any.clear();
    for (const Vec2& p : run) nearest_any.push_back(d.nearest(p));
    const std::uint32_t stroke = d.stroke_marked_by(nearest_any, ids);
    for (std::size_t i = 0; i < run.size(); ++i) {
      const SegmentGrid::Nearest n = d.stroke_of_segment[nearest_any[i].segment] == stroke
                                         ? nearest_any[i]
                                         : d.nearest(run[i], stroke);
      worst = std::max(worst, n.distance);
      sum_sq += n.distance * n.distance;
      overshoot = std::max(overshoot, d.overshoot_mm(n));
      ++q.lit_points;
    }
  }
  if (q.lit_points == 0) return q;
  q.max_deviation_um = worst * 1e3;
  q.rms_deviation_um = std::sqrt(sum_sq / static_cast<double>(q.lit_points)) * 1e3;
  q.overshoot_um = overshoot * 1e3;

  // Coverage: intended length within the radius of a lit path (segments between lit points).
  std::vector<Segment> lit_segments;
  lit_segments.reserve(q.lit_points);
  for (const auto& run : lit.runs)
    for (std::size_t i = 0; i < run.size(); ++i) lit_segments.push_back({run[i == 0 ? 0 : i - 1], run[i]});
  const double radius = d.options.coverage_radius_mm;
  const SegmentGrid lit_grid(std::move(lit_segments), std::max(radius, fine_cell_mm));
  double covered = 0, total = 0;
  d.for_each_sample([&](std::size_t, const StrokeSample& s) {
    total += s.weight;
    if (lit_grid.any_within(s.p, radius)) covered += s.weight;
  });
  q.coverage = total > 0 ? covered / total : 0;

  // Dose along the strokes relative to the ideal constant-speed mark of the same strokes. The
  // ideal leaves 1 s of full power per mm, so each ratio is also the energy per mm there.
  std::vector<Weighted> ratio, stroke_ratio;
  ratio.reserve(d.sample_count());
  double least_stroke = std::numeric_limits<double>::infinity();
  for (const Data::Stroke& stroke : d.strokes) {
    // A stroke's median is its energy per mm.
    stroke_ratio.clear();
    double length = 0;
    for (std::size_t j = stroke.first_segment; j <= stroke.last_segment; ++j)
      d.for_each_sample_of(j, [&](std::size_t i, const StrokeSample& s) {
        length += s.weight;
        if (d.ideal_dose[i] <= 0) return;
        const double r = dose.sum_disc(s.p, d.options.dose_window_mm) / d.ideal_dose[i];
        ratio.push_back({r, s.weight});
        stroke_ratio.push_back({r, s.weight});
      });
    if (length > 0 && !stroke_ratio.empty()) least_stroke = std::min(least_stroke, length_median(stroke_ratio));
  }
  double top = 0;
  for (const Weighted& w : ratio) top = std::max(top, w.value);
  const double mid = length_median(std::move(ratio));
  q.dose_ratio_max = mid > 0 ? top / mid : (top > 0 ? no_median_ratio : 0);
  const auto share_of = [&](double reference_s_per_mm) {
    if (std::isinf(least_stroke)) return 1.0;  // only dwell dots: nothing has a per-mm figure
    return reference_s_per_mm > 0 ? least_stroke / reference_s_per_mm : 0.0;
  };
  q.material_dose_per_mm_fraction = intent.material_dose_s_per_mm > 0 ? share_of(intent.material_dose_s_per_mm) : 0;
  q.dose_vs_material = intent.dose_vs_material;
  q.dose_per_mm_fraction = intent.dose_vs_material ? share_of(intent.material_dose_s_per_mm)
                                                   : share_of(intent.nominal_dose_s_per_mm);

  // Continuity: spots of consecutive pulses must touch along the centre line.
  if (intent.pulses) {
    q.spot_diameter_um = intent.pulses->spot_diameter_um;
    q.pulse_gap_max_um = std::max(0.0, intent.pulses->spacing_max_um - intent.pulses->spot_diameter_um);
  }
  return q;
}

Quality evaluate_quality(const std::vector<std::vector<Vec2>>& intended_polylines,
                         const LitPaths& lit, const DoseRaster& dose, const MarkIntent& intent,
                         QualityOptions options) {
  return QualityReference(intended_polylines, options, dose.pixel_mm()).evaluate(lit, dose, intent);
}

Quality worse_of(const Quality& a, const Quality& b) {
  Quality q;
  q.max_deviation_um = std::max(a.max_deviation_um, b.max_deviation_um);
  q.rms_deviation_um = std::max(a.rms_deviation_um, b.rms_deviation_um);
  q.coverage = std::min(a.coverage, b.coverage);
  q.dose_ratio_max = std::max(a.dose_ratio_max, b.dose_ratio_max);
  q.overshoot_um = std::max(a.overshoot_um, b.overshoot_um);
  // The gap is judged against its own spot: keep the pair whose gap is the larger share of it.
  const auto share = [](const Quality& x) {
    return x.spot_diameter_um > 0 ? x.pulse_gap_max_um / x.spot_diameter_um : 0.0;
  };
  const Quality& gappier = share(b) > share(a) ? b : a;
  q.pulse_gap_max_um = gappier.pulse_gap_max_um;
  q.spot_diameter_um = gappier.spot_diameter_um;
  q.dose_per_mm_fraction = std::min(a.dose_per_mm_fraction, b.dose_per_mm_fraction);
  q.dose_vs_material = a.dose_vs_material || b.dose_vs_material;
  // 0 is "not known", not the least share.
  const double ma = a.material_dose_per_mm_fraction, mb = b.material_dose_per_mm_fraction;
  q.material_dose_per_mm_fraction = ma <= 0 ? mb : mb <= 0 ? ma : std::min(ma, mb);
  q.lit_points = std::min(a.lit_points, b.lit_points);
  return q;
}

}  // namespace mark
