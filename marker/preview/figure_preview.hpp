#pragma once
// Preview of a Figure as SVG or PNG (by the file's extension): the field frame, marks as solid
// lines, travel between strokes dashed, the circle of a circular fitting as a dashed guide, and
// under the picture a scale bar and a legend.
#include <optional>
#include <string>

#include "base/progress.hpp"
#include "marker/layout/figure.hpp"
#include "marker/layout/layout.hpp"

namespace mark {

struct PreviewOptions {
  double px_per_mm = 0;  // 0: the field fills about 1200 px
  bool show_travel = true;
  std::optional<CircleFit> circle;  // circular fitting: the circle the letters stand on
  const Progress* progress = &Progress::none();  // told every few hundred glyphs; may stop the drawing
};

// Throws InputError naming the file if it cannot be written or its extension is not .svg/.png.
void write_figure_preview(const Figure& figure, const Field& field, const std::string& path,
                          const PreviewOptions& options = {});

}  // namespace mark
