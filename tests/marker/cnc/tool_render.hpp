#pragma once
// Test support: synthetic back-lit tool images — a dark tool on a bright background, anti-aliased
// by 8×8 supersampling near the edge, optionally blurred and noisy, quantised to 8 bits like a
// camera — and writers for PGM and PNG files.
#include <functional>
#include <string>

#include "fonts/box.hpp"
#include "marker/image/gray_image.hpp"

namespace mark::test {

struct Render {
  int size = 400;
  double dark = 0.1, bright = 0.9;
  double blur_px = 0;   // Gaussian sigma
  double noise = 0;     // sigma of additive noise, intensity units
  unsigned seed = 7;
};

// `inside(x, y)`: is the point (pixels, y down) part of the tool? `near_edge(x, y)`: might the
// pixel centred at (x, y) straddle the edge (only those are supersampled)?
GrayImage render(const Render& r, const std::function<bool(double, double)>& inside,
                 const std::function<bool(double, double)>& near_edge);
GrayImage disk(const Render& r, Point center, double radius);

// Under <build>/tool_images/; return the path.
std::string write_pgm(const GrayImage& img, const std::string& name);
std::string write_png(const GrayImage& img, const std::string& name);

}  // namespace mark::test
