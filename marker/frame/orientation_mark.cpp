#include "marker/frame/orientation_mark.hpp"

#include <algorithm>

#include "base/error.hpp"

namespace mark {

std::vector<Vec2> letter_f(double x, double y, double h) {
  const double bar = 0.6 * h, middle = 0.55 * h, middle_bar = 0.45 * h;
  return {{x, y}, {x, y + h}, {x + bar, y + h}, {x, y + h}, {x, y + middle}, {x + middle_bar, y + middle}};
}

std::vector<Vec2> orientation_mark(const Box& job, double field_mm) {
  if (job.empty()) throw InputError("frame: the job marks nothing, there is no place for the orientation mark");
  const double half = field_mm / 2;
  const double h = std::clamp(job.height(), 2.0, 10.0), w = 0.6 * h, gap = 0.5 * h;
  const double y = std::clamp(job.center().y() - h / 2, -half, half - h);
  const auto fits = [&](double x) { return x >= -half && x + w <= half; };
  double x = job.max.x() + gap;  // at +x: where an F belongs
  if (!fits(x)) x = job.min.x() - gap - w;
  if (!fits(x)) x = std::clamp(job.center().x() - w / 2, -half, half - w);
  return letter_f(x, y, h);
}

}  // namespace mark
