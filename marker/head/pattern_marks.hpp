#pragma once
// A picture of a test pattern seen as marks: Otsu's threshold splits it in two, and the side
// with fewer pixels is the marks (dark marks on a light part, or light on a dark one). Shared by
// the lag fit (the lines' ends) and the corner fit (the second legs' centres).
#include <string>

#include "marker/image/gray_image.hpp"

namespace mark {

// Otsu's threshold over 256 bins of 0..1: the level that best splits the picture in two.
double otsu_threshold(const GrayImage& g);

// A figure for the fits' messages: four significant digits.
std::string pattern_figure(double v);

class PatternMarks {
 public:
  explicit PatternMarks(const GrayImage& g);
  // > 0 on a mark, < 0 on the surface: the grey's distance from the threshold towards the marks.
  double ink(int x, int y) const {
    const double v = g_.at(x, y);
    return dark_ ? t_ - v : v - t_;
  }
  bool dark() const { return dark_; }
  int width() const { return g_.width; }
  int height() const { return g_.height; }

 private:
  const GrayImage& g_;
  double t_;
  bool dark_ = true;
};

}  // namespace mark
