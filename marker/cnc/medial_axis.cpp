#include "marker/cnc/medial_axis.hpp"

#include <algorithm>
#include <boost/polygon/voronoi.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <unordered_map>

#include "base/error.hpp"
#include "marker/cnc/element_distance.hpp"
#include "marker/geometry/clipper_paths.hpp"

namespace mark::axis_detail {

struct IPoint {
  std::int32_t x, y;
};
struct ISegment {
  IPoint a, b;
};

}  // namespace mark::axis_detail

namespace boost::polygon {

template <>
struct geometry_concept<mark::axis_detail::IPoint> {
  using type = point_concept;
};
template <>
struct point_traits<mark::axis_detail::IPoint> {
  using coordinate_type = std::int32_t;
  static coordinate_type get(const mark::axis_detail::IPoint& p, orientation_2d o) {
    return o == HORIZONTAL ? p.x : p.y;
  }
};
template <>
struct geometry_concept<mark::axis_detail::ISegment> {
  using type = segment_concept;
};
template <>
struct segment_traits<mark::axis_detail::ISegment> {
  using coordinate_type = std::int32_t;
  using point_type = mark::axis_detail::IPoint;
  static point_type get(const mark::axis_detail::ISegment& s, direction_1d d) { return d.to_int() ? s.b : s.a; }
};

}  // namespace boost::polygon

namespace mark {
namespace {

using axis_detail::IPoint;
using axis_detail::ISegment;
using VD = boost::polygon::voronoi_diagram<double>;

constexpr int kMaxSubdivision = 24;

double cross(const Point& a, const Point& b) { return a.x() * b.y() - a.y() * b.x(); }
Point mm_of(const IPoint& p) { return Point(p.x / kNmPerMm, p.y / kNmPerMm); }

// The outline as segments, each ring's interior on the left of its segments.
class Outline {
 public:
  explicit Outline(const ClipperLib::Paths& region) {
    ClipperLib::Paths clean;
    ClipperLib::CleanPolygons(region, clean, 2.0);  // 2 nm: repeated and collinear vertices out
    const auto fits = [](ClipperLib::cInt v) {
      return v >= std::numeric_limits<std::int32_t>::min() && v <= std::numeric_limits<std::int32_t>::max();
    };
    for (const ClipperLib::Path& ring : clean) {
      if (ring.size() < 3) continue;
      const std::size_t first = segs_.size();
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const ClipperLib::IntPoint& a = ring[i];
        const ClipperLib::IntPoint& b = ring[(i + 1) % ring.size()];
        if (!fits(a.X) || !fits(a.Y))
          throw InputError("v-carve: an outline point lies " + std::to_string(std::max(std::abs(a.X), std::abs(a.Y)) / kNmPerMm) +
                           " mm from the letter's origin, beyond the 2147 mm the medial axis can take");
        segs_.push_back({{static_cast<std::int32_t>(a.X), static_cast<std::int32_t>(a.Y)},
                         {static_cast<std::int32_t>(b.X), static_cast<std::int32_t>(b.Y)}});
        prev_.push_back(i == 0 ? first + ring.size() - 1 : segs_.size() - 2);
      }
    }
    next_.resize(segs_.size());
    for (std::size_t s = 0; s < segs_.size(); ++s) next_[prev_[s]] = s;
  }

  const std::vector<ISegment>& segments() const { return segs_; }
  Point a(std::size_t s) const { return mm_of(segs_[s].a); }
  Point b(std::size_t s) const { return mm_of(segs_[s].b); }
  // The segment that ends where segment s starts.
  std::size_t before(std::size_t s) const { return prev_[s]; }
  // The segment that starts where segment s ends.
  std::size_t after(std::size_t s) const { return next_[s]; }
  bool left_of(std::size_t s, const Point& m) const { return cross(b(s) - a(s), m - a(s)) > 0; }

 private:
  std::vector<ISegment> segs_;
  std::vector<std::size_t> prev_, next_;
};

// What a Voronoi cell stands for: an outline point (a corner) or a segment, in mm.
struct Site {
  bool is_point = false;
  Point p{0, 0};          // the corner
  Point a{0, 0}, b{0, 0}; // the segment
  std::size_t in = 0, out = 0;  // corner: the segments that end and start there; segment: itself

  double distance(const Point& x) const { return is_point ? (x - p).norm() : distance_to_segment(x, a, b); }
};

Site site_of(const VD::cell_type& cell, const Outline& o) {
  Site s;
  const std::size_t k = cell.source_index();
  if (cell.contains_segment()) {
    s.a = o.a(k);
    s.b = o.b(k);
    s.in = s.out = k;
    return s;
  }
  s.is_point = true;
  if (cell.source_category() == boost::polygon::SOURCE_CATEGORY_SEGMENT_START_POINT) {
    s.p = o.a(k);
    s.out = k;
    s.in = o.before(k);
  } else {  // the end point of segment k is the start of the next one
    s.p = o.b(k);
    s.in = k;
    s.out = o.after(k);
  }
  return s;
}

// Is m inside the region, judged by the outline feature nearest to it (the cell's site)?
bool inside(const Site& s, const Outline& o, const Point& m) {
  if (!s.is_point) return o.left_of(s.in, m);
  const bool convex = cross(o.b(s.in) - o.a(s.in), o.b(s.out) - o.a(s.out)) >= 0;
  return convex ? o.left_of(s.in, m) && o.left_of(s.out, m) : o.left_of(s.in, m) || o.left_of(s.out, m);
}

// A Voronoi edge as a curve: position and radius at parameter u ∈ [0, 1].
class EdgeCurve {
 public:
  EdgeCurve(const Site& s0, const Site& s1, const Point& v0, const Point& v1) : s0_(s0), s1_(s1), v0_(v0), v1_(v1) {
    parabolic_ = s0.is_point != s1.is_point;
    if (!parabolic_) return;
    const Site& pt = s0.is_point ? s0 : s1;
    const Site& sg = s0.is_point ? s1 : s0;
    origin_ = sg.a;
    u_ = (sg.b - sg.a).normalized();
    n_ = Point(-u_.y(), u_.x());
    ph_ = (pt.p - origin_).dot(n_);
    if (ph_ < 0) {
      n_ = -n_;
      ph_ = -ph_;
    }
    pt_ = (pt.p - origin_).dot(u_);
    t0_ = (v0 - origin_).dot(u_);
    t1_ = (v1 - origin_).dot(u_);
  }
  // A focus on the directrix cannot happen for a primary edge; treat it as straight.
  bool curved() const { return parabolic_ && ph_ > 0; }

  Point at(double u) const {
    if (u <= 0) return v0_;
    if (u >= 1) return v1_;
    if (!curved()) return v0_ + u * (v1_ - v0_);
    const double t = t0_ + u * (t1_ - t0_);
    const double h = ((t - pt_) * (t - pt_) + ph_ * ph_) / (2 * ph_);
    return origin_ + t * u_ + h * n_;
  }
  // Distance to the outline at x (on or near the edge): to the nearer of its two sites.
  double radius(const Point& x) const { return std::min(s0_.distance(x), s1_.distance(x)); }

 private:
  Site s0_, s1_;
  Point v0_, v1_;
  bool parabolic_ = false;
  Point origin_{0, 0}, u_{1, 0}, n_{0, 1};
  double ph_ = 0, pt_ = 0, t0_ = 0, t1_ = 0;
};

// Samples from u0 to u1 (u0's sample already taken) until position and linearly interpolated
// radius stay within tol of the edge between samples.
void subdivide(const EdgeCurve& c, double u0, const AxisSample& s0, double u1, const AxisSample& s1, double tol,
               int depth, std::vector<AxisSample>& out, double& max_excess) {
  const double um = (u0 + u1) / 2;
  const Point pm = c.at(um);
  const Point chord_mid = (s0.p + s1.p) / 2;
  const double excess = (s0.r + s1.r) / 2 - c.radius(chord_mid);
  if (depth < kMaxSubdivision && ((pm - chord_mid).norm() > tol || excess > tol)) {
    const AxisSample sm{pm, c.radius(pm)};
    subdivide(c, u0, s0, um, sm, tol, depth + 1, out, max_excess);
    subdivide(c, um, sm, u1, s1, tol, depth + 1, out, max_excess);
    return;
  }
  max_excess = std::max(max_excess, excess);
  out.push_back(s1);
}

struct Node {
  Point p{0, 0};
  double r = 0;
  std::vector<std::size_t> edges;      // live incident edges
  std::vector<AxisSample> covers;      // discs of pruned branches this node's disc must cover
};

struct Edge {
  std::size_t n0 = 0, n1 = 0;
  std::vector<AxisSample> samples;     // from n0 to n1
  bool alive = true;
  bool walked = false;
  std::size_t other(std::size_t n) const { return n == n0 ? n1 : n0; }
};

class Graph {
 public:
  std::vector<Node> nodes;
  std::vector<Edge> edges;

  std::size_t degree(std::size_t n) const { return nodes[n].edges.size(); }

  void remove(std::size_t e) {
    edges[e].alive = false;
    for (std::size_t n : {edges[e].n0, edges[e].n1}) {
      auto& list = nodes[n].edges;
      list.erase(std::remove(list.begin(), list.end(), e), list.end());
    }
  }

  // Leaf branches whose every disc lies within tol of the disc where they join the rest.
  std::size_t prune(double tol) {
    std::size_t pruned = 0;
    std::vector<std::size_t> leaves;
    for (std::size_t n = 0; n < nodes.size(); ++n)
      if (degree(n) == 1) leaves.push_back(n);
    while (!leaves.empty()) {
      const std::size_t leaf = leaves.back();
      leaves.pop_back();
      if (degree(leaf) != 1) continue;
      const std::size_t e = nodes[leaf].edges.front();
      const std::size_t to = edges[e].other(leaf);
      if (degree(to) == 1) continue;  // the last edge of its piece: keep it
      const Node& keep = nodes[to];
      const auto covered = [&](const AxisSample& d) { return (d.p - keep.p).norm() + d.r <= keep.r + tol; };
      const std::vector<AxisSample>& own = nodes[leaf].covers;
      if (!std::all_of(own.begin(), own.end(), covered) ||
          !std::all_of(edges[e].samples.begin(), edges[e].samples.end(), covered))
        continue;
      auto& inherit = nodes[to].covers;
      inherit.insert(inherit.end(), own.begin(), own.end());
      inherit.insert(inherit.end(), edges[e].samples.begin(), edges[e].samples.end());
      remove(e);
      ++pruned;
      if (degree(to) == 1) leaves.push_back(to);
    }
    return pruned;
  }

  // Walks every live edge once, going straight on at junctions; odd-degree nodes first so the
  // walks end where branches end.
  std::vector<AxisPath> walk() {
    std::vector<AxisPath> paths;
    std::vector<std::size_t> starts;
    for (std::size_t n = 0; n < nodes.size(); ++n)
      if (degree(n) % 2 == 1) starts.push_back(n);
    for (std::size_t n = 0; n < nodes.size(); ++n)
      if (degree(n) > 0 && degree(n) % 2 == 0) starts.push_back(n);
    for (std::size_t start : starts) {
      while (std::size_t e = next_unwalked(start, std::nullopt)) {
        AxisPath path;
        std::size_t at = start;
        std::optional<Point> heading;
        for (std::size_t cur = e; cur;) {
          Edge& edge = edges[cur - 1];
          edge.walked = true;
          const bool forward = edge.n0 == at;
          std::vector<AxisSample> s = edge.samples;
          if (!forward) std::reverse(s.begin(), s.end());
          path.insert(path.end(), path.empty() ? s.begin() : s.begin() + 1, s.end());
          at = edge.other(at);
          heading = (s.back().p - s[s.size() - 2].p);
          cur = next_unwalked(at, heading);
        }
        paths.push_back(std::move(path));
      }
    }
    return paths;
  }

 private:
  // 1 + the unwalked live edge at n that turns least from `heading` (any, without one); 0: none.
  std::size_t next_unwalked(std::size_t n, const std::optional<Point>& heading) const {
    std::size_t best = 0;
    double best_cos = -2;
    for (std::size_t e : nodes[n].edges) {
      if (edges[e].walked) continue;
      if (!heading) return e + 1;
      const Edge& edge = edges[e];
      const bool forward = edge.n0 == n;
      const Point& first = forward ? edge.samples[1].p : edge.samples[edge.samples.size() - 2].p;
      const Point dir = first - nodes[n].p;
      const double c = heading->norm() > 0 && dir.norm() > 0 ? heading->normalized().dot(dir.normalized()) : -1;
      if (c > best_cos) {
        best_cos = c;
        best = e + 1;
      }
    }
    return best;
  }
};

}  // namespace

MedialAxis medial_axis(const ClipperLib::Paths& region, double tol) {
  const Outline outline(region);
  VD vd;
  boost::polygon::construct_voronoi(outline.segments().begin(), outline.segments().end(), &vd);

  Graph g;
  std::unordered_map<const VD::vertex_type*, std::size_t> node_of;
  const auto node = [&](const VD::vertex_type* v, const EdgeCurve& c) {
    auto [it, fresh] = node_of.emplace(v, g.nodes.size());
    if (fresh) {
      Node n;
      n.p = Point(v->x() / kNmPerMm, v->y() / kNmPerMm);
      n.r = c.radius(n.p);
      g.nodes.push_back(n);
    }
    return it->second;
  };

  MedialAxis out;
  for (const VD::edge_type& e : vd.edges()) {
    if (!e.is_primary() || !e.is_finite() || &e > e.twin()) continue;
    const Site s0 = site_of(*e.cell(), outline), s1 = site_of(*e.twin()->cell(), outline);
    const Point v0(e.vertex0()->x() / kNmPerMm, e.vertex0()->y() / kNmPerMm);
    const Point v1(e.vertex1()->x() / kNmPerMm, e.vertex1()->y() / kNmPerMm);
    const EdgeCurve curve(s0, s1, v0, v1);
    if (!inside(s0, outline, curve.at(0.5))) continue;
    Edge edge;
    edge.n0 = node(e.vertex0(), curve);
    edge.n1 = node(e.vertex1(), curve);
    if (edge.n0 == edge.n1) continue;
    const AxisSample a{g.nodes[edge.n0].p, g.nodes[edge.n0].r}, b{g.nodes[edge.n1].p, g.nodes[edge.n1].r};
    edge.samples.push_back(a);
    subdivide(curve, 0, a, 1, b, tol, 0, edge.samples, out.max_radius_excess_mm);
    g.edges.push_back(std::move(edge));
    for (std::size_t n : {g.edges.back().n0, g.edges.back().n1}) g.nodes[n].edges.push_back(g.edges.size() - 1);
  }
  out.voronoi_edges = g.edges.size();
  out.pruned_edges = g.prune(tol);
  out.paths = g.walk();
  return out;
}

}  // namespace mark
