#pragma once
// The medial axis of a polygonal region — the centres of its maximal inscribed discs, each with
// its radius (the distance to the outline) — computed exactly from Boost.Polygon's Voronoi
// diagram of the outline's segments (boost/polygon/voronoi.hpp: integer input, exact
// predicates), not by growing circles at sampled points as F-Engrave does.
//
// From the diagram: the primary edges inside the region (an edge between a segment and its own
// end point is not part of the axis: a disc there touches the outline at one point only).
// Edges whose radius is not linear along them — parabolic arcs between a corner and a side,
// bisectors of two corners — are sampled so that neither the position nor the radius strays
// more than the tolerance between samples. Then the branches that end in a convex corner of the
// outline and add nothing beyond the tolerance are pruned: a polygon flattened from a curve has
// a corner at every chord, each with a branch of its own, and every disc along such a branch
// lies within the tolerance of the disc where it joins the rest (a branch into a real corner of
// a letter does not, and stays). Last, the axis is walked into paths, going straight on at
// junctions, so a cutter following it lifts as little as it can.
#include <polyclipping/clipper.hpp>

#include <vector>

#include "fonts/box.hpp"

namespace mark {

struct AxisSample {
  Point p{0, 0};   // mm
  double r = 0;    // distance to the outline, mm
};

using AxisPath = std::vector<AxisSample>;  // at least two samples

struct MedialAxis {
  std::vector<AxisPath> paths;
  std::size_t voronoi_edges = 0;  // primary edges inside the region, before pruning
  std::size_t pruned_edges = 0;   // of those, dropped as adding nothing beyond the tolerance
  // The most a radius interpolated linearly between two samples exceeds the true distance to
  // the outline (checked at the middle of every sample interval; 0 where the radius is linear,
  // as between two sides).
  double max_radius_excess_mm = 0;
};

// `region`: closed polygons in integer nanometres as Clipper returns them from a union (outer
// boundaries counter-clockwise, holes clockwise, no self-intersection), every coordinate within
// ±2^31 nm. Throws InputError beyond that range.
MedialAxis medial_axis(const ClipperLib::Paths& region, double tolerance_mm);

}  // namespace mark
