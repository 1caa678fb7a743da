#include "marker/cnc/tool/tool_measure.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "base/error.hpp"
#include "marker/cnc/tool/edge_scan.hpp"

namespace mark {
namespace {

constexpr std::size_t kMinPoints = 12;
constexpr double kMinContrast = 0.1;      // of the full intensity range
constexpr double kOutlierMadFactor = 4;   // robust sigmas beyond which a point is a defect
constexpr double kOutlierFloorPx = 0.5;   // never call sub-half-pixel scatter a defect

std::vector<Point> positions(const std::vector<EdgePoint>& e) {
  std::vector<Point> p;
  p.reserve(e.size());
  for (const EdgePoint& x : e) p.push_back(x.position_px);
  return p;
}

double median(std::vector<double> v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace

ToolMeasurement measure_tool(const GrayImage& img, const ToolMeasureOptions& o, const std::string& src) {
  if (!(o.pixel_size_um > 0) || !std::isfinite(o.pixel_size_um))
    throw InputError(src + ": pixel size must be a positive number of micrometres");
  if (o.nominal_diameter_mm && !(*o.nominal_diameter_mm > 0))
    throw InputError(src + ": nominal diameter must be positive");
  if (img.width < 3 || img.height < 3) throw InputError(src + ": image too small to hold a tool edge");
  const EdgeLevels lv = edge_levels(img);
  if (lv.contrast() < kMinContrast) {
    std::ostringstream m;
    m << src << ": no shadow edge: the image's dark and bright levels differ by only " << lv.contrast();
    throw InputError(m.str());
  }
  const std::vector<EdgePoint> edges = scan_edges(img, lv, o.sharpness);
  if (edges.size() < kMinPoints)
    throw InputError(src + ": only " + std::to_string(edges.size()) +
                     " sharp intensity transitions found; the tool edge is not in the picture");

  ToolMeasurement m;
  m.edge_points = edges.size();
  // First centre from every transition.
  const Circle first = fit_circle_geometric(positions(edges), fit_circle_algebraic(positions(edges)));
  // Drop the points whose scan ran tangentially along the edge.
  const double min_cos = std::cos(o.tangential_angle_deg * std::numbers::pi / 180);
  std::vector<Point> kept;
  for (const EdgePoint& e : edges) {
    const Point n = e.position_px - first.center;
    if (n.norm() > 0 && std::abs(e.scan_dir.dot(n / n.norm())) >= min_cos - 1e-12) kept.push_back(e.position_px);
  }
  m.tangential_dropped = edges.size() - kept.size();
  if (kept.size() < kMinPoints) throw InputError(src + ": the edge points do not go round a tool");
  const Circle second = fit_circle_geometric(kept, fit_circle_algebraic(kept));
  // Defects (a chipped or worn spot) are reported, but must not pull the circle.
  std::vector<double> res;
  for (const Point& p : kept) res.push_back((p - second.center).norm() - second.radius);
  const double med = median(res);
  std::vector<double> dev;
  for (double r : res) dev.push_back(std::abs(r - med));
  const double limit = std::max(kOutlierMadFactor * 1.4826 * median(dev), kOutlierFloorPx);
  std::vector<Point> inliers;
  for (std::size_t i = 0; i < kept.size(); ++i)
    if (std::abs(res[i] - med) <= limit) inliers.push_back(kept[i]);
  m.outliers = kept.size() - inliers.size();
  m.circle_px = inliers.size() >= kMinPoints ? fit_circle_geometric(inliers, second) : second;

  const double mm_per_px = o.pixel_size_um / 1000;
  m.radius_mm = m.circle_px.radius * mm_per_px;
  m.diameter_mm = 2 * m.radius_mm;
  m.center_mm = m.circle_px.center * mm_per_px;
  double sum2 = 0, worst = -1, worst_nominal = 0;
  for (const Point& p : kept) {
    const Point d = p - m.circle_px.center;
    const double r = d.norm() - m.circle_px.radius;
    sum2 += r * r;
    if (std::abs(r) > worst) {
      worst = std::abs(r);
      m.form_deviation_angle_deg = std::atan2(-d.y(), d.x()) * 180 / std::numbers::pi;
    }
    if (o.nominal_diameter_mm)
      worst_nominal = std::max(worst_nominal, std::abs(d.norm() * mm_per_px - *o.nominal_diameter_mm / 2));
  }
  m.form_deviation_mm = worst * mm_per_px;
  m.rms_mm = std::sqrt(sum2 / static_cast<double>(kept.size())) * mm_per_px;
  if (o.nominal_diameter_mm) {
    m.size_deviation_mm = m.radius_mm - *o.nominal_diameter_mm / 2;
    m.nominal_form_deviation_mm = worst_nominal;
  }
  return m;
}

}  // namespace mark
