#pragma once
// The serial-number job several suites mark to compare one path with another: "SN 20260042",
// 1.5 mm, centred just above the field's middle, on SL10 with a blanking pen at `speed_mm_s`.
#include "fonts/catalog.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/job.hpp"

namespace mark::test {

inline JobSpec serial_job(double speed_mm_s = 300) {
  JobSpec spec;
  spec.text = "SN 20260042";
  spec.font = open_font(kBuiltinFontName);
  spec.layout.height_mm = 1.5;
  spec.layout.align = Align::center;
  spec.layout.base = Point(0, 0.5);
  spec.head = head_sl10();
  spec.pen = pen_for_head(spec.head, CornerStrategy::blanking, speed_mm_s);
  return spec;
}

}  // namespace mark::test
