#include "marker/head/lag_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "base/error.hpp"
#include "marker/head/head_file.hpp"

namespace mark {
namespace {

constexpr const char* kPatternFormat = "marker lag pattern";
constexpr int kPatternVersion = 1;
constexpr double kCornerRowGap_mm = 1.5;  // between the corners' rows, and above them


// Lays the lines out from the pattern's parameters (one function, so a parsed pattern is the
// very one that was marked).
void lay_out(LagPattern& p, Vec2 centre) {
  const int rows = 2 * static_cast<int>(p.speeds_mm_s.size());
  const double block = (rows - 1) * p.pitch_mm;
  const double width = p.length_mm + p.gap_mm + block;
  const double x0 = centre.x - width / 2, y0 = centre.y - p.length_mm / 2;
  const double top = y0 + p.length_mm;
  p.lines.clear();
  for (int axis = 0; axis < 2; ++axis)
    for (int i = 0; i < rows; ++i) {
      LagLine l;
      l.axis = axis;
      l.forward = i % 2 == 0;
      l.speed_mm_s = p.speeds_mm_s[static_cast<std::size_t>(i / 2)];
      if (axis == 0) {
        const double y = top - i * p.pitch_mm;
        l.start = {x0, y};
        l.end = {x0 + p.length_mm, y};
      } else {
        const double x = x0 + p.length_mm + p.gap_mm + i * p.pitch_mm;
        l.start = {x, y0};
        l.end = {x, top};
      }
      if (!l.forward) std::swap(l.start, l.end);
      p.lines.push_back(l);
    }
  // The corners below the x rows: the first row's leg along the pattern's bottom edge (where the
  // y lines start), each corner `leg + 2` mm right of the last.
  p.corners.clear();
  const double leg = p.corner_leg_mm;
  for (std::size_t i = 0; leg > 0 && i < p.corner_speeds_mm_s.size(); ++i) {
    const double x = x0 + static_cast<double>(i) * (leg + 2);
    const double v = p.corner_speeds_mm_s[i];
    p.corners.push_back({0, v, {x, y0}, {x + leg, y0}, {x + leg, y0 + leg}});
    const double y = y0 + leg + kCornerRowGap_mm;
    p.corners.push_back({1, v, {x, y}, {x, y + leg}, {x + leg, y + leg}});
  }
}

// The corners' rows must lie inside the lines' extent and clear of the x rows (their strip in
// the fit reaches half a pitch below the last row).
bool corners_fit(const LagPattern& p) {
  if (p.corners.empty()) return true;
  double right = -1e300, top = -1e300;
  for (const LagCorner& c : p.corners) right = std::max(right, c.end.x), top = std::max(top, c.end.y);
  double lowest_row = 1e300, x_end = -1e300;
  for (const LagLine& l : p.lines)
    if (l.axis == 0) lowest_row = std::min(lowest_row, l.start.y), x_end = std::max({x_end, l.start.x, l.end.x});
  return right <= x_end + 1e-9 && top + kCornerRowGap_mm <= lowest_row + 1e-9;
}

void check_field(const LagPattern& p, const HeadModel& head) {
  const double half = head.field_mm / 2;
  const Vec2 lo = p.min(), hi = p.max();
  if (lo.x < -half || lo.y < -half || hi.x > half || hi.y > half) {
    std::ostringstream m;
    m << "lag pattern: " << hi.x - lo.x << " × " << hi.y - lo.y << " mm about ("
      << (lo.x + hi.x) / 2 << ", " << (lo.y + hi.y) / 2 << ") does not fit the "
      << head.field_mm << " mm field of head " << head.name;
    throw InputError(m.str());
  }
}

constexpr HeadFileKind kPatternKind{"lag pattern", kPatternFormat, kPatternVersion};

double number(const nlohmann::json& j, const char* key, double lo, double hi, std::string_view where) {
  return head_file_number(kPatternKind, j, key, lo, hi, where);
}

}  // namespace

double LagPattern::fastest_mm_s() const {
  double fastest = 0;
  for (const LagLine& l : lines) fastest = std::max(fastest, l.speed_mm_s);
  return fastest;
}

Vec2 LagPattern::min() const {
  Vec2 m{1e300, 1e300};
  for (const LagLine& l : lines)
    m = {std::min({m.x, l.start.x, l.end.x}), std::min({m.y, l.start.y, l.end.y})};
  return m;
}

Vec2 LagPattern::max() const {
  Vec2 m{-1e300, -1e300};
  for (const LagLine& l : lines)
    m = {std::max({m.x, l.start.x, l.end.x}), std::max({m.y, l.start.y, l.end.y})};
  return m;
}

LagPattern lag_pattern(const HeadModel& head, Vec2 centre) {
  LagPattern p;
  p.head = head.name;
  const double top = 0.4 * head.max_speed_mm_s;
  for (double v : {500.0, 1000.0, 2000.0, 3000.0, 4000.0})
    if (v <= top) p.speeds_mm_s.push_back(v);
  for (double v : {250.0, 100.0, 50.0})
    if (p.speeds_mm_s.size() < 3 && v <= top) p.speeds_mm_s.insert(p.speeds_mm_s.begin(), v);
  if (p.speeds_mm_s.size() < 3) {
    std::ostringstream m;
    m << "lag pattern: head " << head.name << " runs at most " << head.max_speed_mm_s
      << " mm/s; the pattern needs three speeds of at least 50 mm/s within 40 % of it";
    throw InputError(m.str());
  }
  for (double v : p.speeds_mm_s)
    if (v <= kLagCornerTopSpeed_mm_s) p.corner_speeds_mm_s.push_back(v);
  if (p.corner_speeds_mm_s.size() > 3) p.corner_speeds_mm_s.erase(p.corner_speeds_mm_s.begin(), p.corner_speeds_mm_s.end() - 3);
  p.corner_leg_mm = kLagCornerLeg_mm;
  lay_out(p, centre);
  if (!corners_fit(p)) {  // no room below the rows: lines only
    p.corner_leg_mm = 0;
    p.corner_speeds_mm_s.clear();
    lay_out(p, centre);
  }
  check_field(p, head);
  return p;
}

std::vector<ScanSample> lag_pattern_samples(const LagPattern& pattern, double tick_s) {
  const double fastest = pattern.fastest_mm_s();
  std::vector<ScanSample> out;
  auto emit = [&](Vec2 p, bool laser, std::uint8_t power) {
    out.push_back({static_cast<float>(p.x), static_cast<float>(p.y), laser, power});
  };
  auto hold = [&](Vec2 p, double seconds) {
    const auto n = static_cast<std::size_t>(std::lround(seconds / tick_s));
    for (std::size_t i = 0; i < n; ++i) emit(p, false, 0);
  };
  for (const LagLine& l : pattern.lines) {
    hold(l.start, kLagJumpSettle_s);
    const double length = norm(l.end - l.start);
    const auto n = static_cast<std::size_t>(std::ceil(length / (l.speed_mm_s * tick_s) - 1e-9));
    const auto power = static_cast<std::uint8_t>(std::clamp(std::lround(255 * l.speed_mm_s / fastest), 1L, 255L));
    for (std::size_t i = 1; i <= n; ++i)
      emit(l.start + (static_cast<double>(i) / static_cast<double>(n)) * (l.end - l.start), true, power);
    hold(l.end, kLagAfterLine_s);
  }
  for (const LagCorner& c : pattern.corners) {
    hold(c.start, kLagJumpSettle_s);
    const auto power = static_cast<std::uint8_t>(std::clamp(std::lround(255 * c.speed_mm_s / fastest), 1L, 255L));
    for (const auto& [a, b] : {std::pair{c.start, c.corner}, std::pair{c.corner, c.end}}) {
      const auto n = static_cast<std::size_t>(std::ceil(norm(b - a) / (c.speed_mm_s * tick_s) - 1e-9));
      for (std::size_t i = 1; i <= n; ++i) emit(a + (static_cast<double>(i) / static_cast<double>(n)) * (b - a), true, power);
    }
    hold(c.end, kLagAfterLine_s);
  }
  return out;
}

std::string lag_pattern_json(const LagPattern& p) {
  const Vec2 lo = p.min(), hi = p.max();
  nlohmann::ordered_json j;
  j["format"] = kPatternFormat;
  j["version"] = kPatternVersion;
  j["head"] = p.head;
  j["centre_mm"] = {(lo.x + hi.x) / 2, (lo.y + hi.y) / 2};
  j["length_mm"] = p.length_mm;
  j["pitch_mm"] = p.pitch_mm;
  j["gap_mm"] = p.gap_mm;
  j["speeds_mm_s"] = p.speeds_mm_s;
  if (!p.corners.empty()) {
    j["corner_leg_mm"] = p.corner_leg_mm;
    j["corner_speeds_mm_s"] = p.corner_speeds_mm_s;
  }
  return j.dump(2) + "\n";
}

LagPattern parse_lag_pattern(std::string_view text, std::string_view where) {
  const nlohmann::json j = parse_head_file(kPatternKind, text, where);
  LagPattern p;
  const auto head = j.find("head");
  if (head != j.end() && head->is_string()) p.head = head->get<std::string>();
  p.length_mm = number(j, "length_mm", 1, 1000, where);
  p.pitch_mm = number(j, "pitch_mm", 0.1, 100, where);
  p.gap_mm = number(j, "gap_mm", 0.5, 100, where);
  const auto centre = j.find("centre_mm");
  if (centre == j.end() || !centre->is_array() || centre->size() != 2 || !(*centre)[0].is_number() ||
      !(*centre)[1].is_number())
    head_file_error(kPatternKind, where, "'centre_mm' must be [x, y]");
  const auto speeds = j.find("speeds_mm_s");
  if (speeds == j.end() || !speeds->is_array() || speeds->size() < 3 || speeds->size() > 20)
    head_file_error(kPatternKind, where, "'speeds_mm_s' must list 3 to 20 speeds");
  for (const auto& s : *speeds) {
    if (!s.is_number() || !(s.get<double>() >= 1 && s.get<double>() <= 1e5))
      head_file_error(kPatternKind, where, "'speeds_mm_s' holds a value outside 1 to 100000 mm/s");
    p.speeds_mm_s.push_back(s.get<double>());
  }
  const Vec2 c{(*centre)[0].get<double>(), (*centre)[1].get<double>()};
  if (!std::isfinite(c.x) || !std::isfinite(c.y) || std::abs(c.x) > 1e4 || std::abs(c.y) > 1e4)
    head_file_error(kPatternKind, where, "'centre_mm' lies outside ±10000 mm");
  // The corners (optional: a pattern file from before they were added has none).
  const auto legs = j.find("corner_leg_mm");
  if (legs != j.end()) {
    p.corner_leg_mm = number(j, "corner_leg_mm", 1, 20, where);
    const auto cs = j.find("corner_speeds_mm_s");
    if (cs == j.end() || !cs->is_array() || cs->empty() || cs->size() > 10)
      head_file_error(kPatternKind, where, "'corner_speeds_mm_s' must list 1 to 10 speeds with 'corner_leg_mm'");
    for (const auto& s : *cs) {
      if (!s.is_number() || !(s.get<double>() >= 1 && s.get<double>() <= 1e5))
        head_file_error(kPatternKind, where, "'corner_speeds_mm_s' holds a value outside 1 to 100000 mm/s");
      // A board marks a corner with its speed's pen (lag_program.cpp).
      if (std::find(p.speeds_mm_s.begin(), p.speeds_mm_s.end(), s.get<double>()) == p.speeds_mm_s.end()) {
        std::ostringstream m;
        m << "'corner_speeds_mm_s' holds " << s.get<double>() << " mm/s, none of 'speeds_mm_s'";
        head_file_error(kPatternKind, where, m.str());
      }
      p.corner_speeds_mm_s.push_back(s.get<double>());
    }
  }
  lay_out(p, c);
  if (!corners_fit(p))
    head_file_error(kPatternKind, where,
                    "the corners ('corner_leg_mm', 'corner_speeds_mm_s') do not fit below the x lines");
  return p;
}

LagPattern load_lag_pattern(const std::string& path) {
  return parse_lag_pattern(read_head_file(kPatternKind, path), path);
}

}  // namespace mark
