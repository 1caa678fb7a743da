#pragma once
// Tool form measurement from a back-lit (shadow) image of the cutter seen along its axis, as in
// US 5,255,199: scan the image along rows and along columns (two orthogonal sets of parallel
// lines), keep the points of sharp intensity transition as edge points (located to a fraction
// of a pixel), fit the tool centre, drop the points whose scan ran tangentially along the edge
// (there a transition is smeared along the scan and badly placed), fit again, and compare the
// actual edge with the assumed size and shape. The measured radius then replaces the nominal
// one in the toolpath offsets (or goes into the D word for control-side compensation).
#include <optional>
#include <string>

#include "marker/cnc/tool/circle_fit.hpp"
#include "marker/image/gray_image.hpp"

namespace mark {

struct ToolMeasureOptions {
  double pixel_size_um = 0;                  // edge length of one pixel at the tool, µm
  std::optional<double> nominal_diameter_mm;  // the assumed tool, for the comparison
  // A scan whose direction makes more than this angle with the edge normal counts as tangential
  // (90 keeps every point).
  double tangential_angle_deg = 60;
  // A transition is sharp when the intensity changes by this share of the contrast within
  // 5 pixels around it (edge_scan.hpp).
  double sharpness = 0.5;
};

struct ToolMeasurement {
  Circle circle_px;          // image pixels: x right, y down, (0, 0) the top-left pixel corner
  double radius_mm = 0;
  double diameter_mm = 0;
  Point center_mm{0, 0};     // from the image's top-left corner, x right, y down
  // Largest distance of an edge point from the fitted circle (chips, wear flats), and where:
  // the angle of that point about the centre, degrees counter-clockwise from +x, y up.
  double form_deviation_mm = 0;
  double form_deviation_angle_deg = 0;
  double rms_mm = 0;         // of all kept edge points about the circle
  std::size_t edge_points = 0;       // transitions found by all scans
  std::size_t tangential_dropped = 0;
  std::size_t outliers = 0;          // kept for the form deviation, left out of the final fit
  // With a nominal diameter: measured − nominal radius (negative = worn), and the largest
  // deviation of an edge point from the nominal circle about the measured centre.
  std::optional<double> size_deviation_mm;
  std::optional<double> nominal_form_deviation_mm;
};

// Throws InputError (naming `source`) for a pixel size ≤ 0, an image without a clear edge, or
// an edge that is not a circle.
ToolMeasurement measure_tool(const GrayImage& image, const ToolMeasureOptions& options,
                             const std::string& source = "tool image");

}  // namespace mark
