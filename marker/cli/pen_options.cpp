#include "marker/cli/pen_options.hpp"

#include "fonts/error.hpp"
#include "marker/common/range_check.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/job_checks.hpp"

namespace mark::cli {

void add_pen_options(CLI::App& app, PenArgs& a) {
  app.add_option("--head", a.head, "scan head preset: SL10, SL14, cheap")->capture_default_str();
  app.add_option("--corner", a.corner, "corner strategy: blanking, delays, none")->capture_default_str();
  app.add_option("--speed", a.speed_mm_s, "marking speed, mm/s")->capture_default_str();
  app.add_option("--jump-speed", a.jump_speed_mm_s, "jump speed, mm/s (default: half the head's positioning limit)");
  app.add_option("--tick", a.tick_us, "locus tick, µs")->capture_default_str();
  app.add_option("--run-in", a.run_in_mm, "blanking run-in length, mm (default: sized by the head's settling)");
  app.add_option("--run-out", a.run_out_mm, "blanking run-out length, mm (default v·τ)");
  app.add_option("--field", a.field_mm, "field size (square), mm")->capture_default_str();
}

HeadAndPen make_head_and_pen(const PenArgs& a) {
  const auto head = find_head(a.head);
  if (!head) throw InputError("--head '" + a.head + "' is not one of SL10, SL14, cheap");
  HeadAndPen hp{*head, {}};
  require_in_range("--field", a.field_mm, 1, 1000, "mm");
  hp.head.field_mm = a.field_mm;
  require_in_range("--speed", a.speed_mm_s, 1, hp.head.max_speed_mm_s, "mm/s");
  if (a.jump_speed_mm_s != 0) require_in_range("--jump-speed", a.jump_speed_mm_s, 1, hp.head.max_speed_mm_s, "mm/s");
  require_in_range("--tick", a.tick_us, kMinTick_s * 1e6, hp.head.max_tick_s() * 1e6, "µs");
  if (a.run_in_mm) require_in_range("--run-in", *a.run_in_mm, 0, 10, "mm");
  if (a.run_out_mm) require_in_range("--run-out", *a.run_out_mm, 0, 10, "mm");
  hp.pen = pen_for_head(hp.head, parse_corner_strategy(a.corner), a.speed_mm_s, a.tick_us * 1e-6);
  if (a.jump_speed_mm_s != 0) {
    hp.pen.jump_speed_mm_s = a.jump_speed_mm_s;
    if (hp.pen.corner == CornerStrategy::blanking) hp.pen.join_speed_mm_s = a.jump_speed_mm_s;
  }
  if (a.run_in_mm) hp.pen.run_in_mm = *a.run_in_mm;
  if (a.run_out_mm) hp.pen.run_out_mm = *a.run_out_mm;
  check_pen(hp.pen, hp.head);
  return hp;
}

}  // namespace mark::cli
