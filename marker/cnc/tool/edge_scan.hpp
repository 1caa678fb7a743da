#pragma once
// Edge points of a shadow image: every row and every column is scanned for sharp intensity
// transitions through the level halfway between the dark tool and the bright background; each
// crossing is placed to a fraction of a pixel by linear interpolation between the two samples
// that straddle the level.
#include <vector>

#include "fonts/box.hpp"
#include "marker/image/gray_image.hpp"

namespace mark {

struct EdgePoint {
  Point position_px;  // x right, y down, pixel (i, j) covers [i, i+1) × [j, j+1)
  Point scan_dir;     // (1, 0) for a row scan, (0, 1) for a column scan
};

struct EdgeLevels {
  float dark = 0, bright = 1;
  float threshold() const { return (dark + bright) / 2; }
  float contrast() const { return bright - dark; }
};

// Dark and bright levels: the 2nd and 98th percentiles of the intensities.
EdgeLevels edge_levels(const GrayImage& image);

// A crossing counts when the intensity changes by at least `sharpness` × the contrast within
// 5 pixels around it (noise in flat areas does not).
std::vector<EdgePoint> scan_edges(const GrayImage& image, const EdgeLevels& levels, double sharpness = 0.5);

}  // namespace mark
