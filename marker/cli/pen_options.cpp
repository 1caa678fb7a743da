#include "marker/cli/pen_options.hpp"

#include "fonts/error.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/job_checks.hpp"
#include "marker/limits/layout_limits.hpp"
#include "marker/limits/pen_limits.hpp"

namespace mark::cli {

void add_pen_options(CLI::App& app, PenArgs& a) {
  app.add_option("--head", a.head, "scan head preset: SL10, SL14, cheap")->capture_default_str();
  app.add_option("--corner", a.corner, "corner strategy: blanking, delays, none")->capture_default_str();
  add_ranged_option(app, "--speed", a.speed_mm_s, "marking speed, mm/s (at most the head's limit)", kSpeedRange)
      ->capture_default_str();
  add_ranged_option(app, "--jump-speed", a.jump_speed_mm_s,
                    "jump speed, mm/s (0: half the head's positioning limit; at most the limit)",
                    Range{1, kSpeedRange.max, "mm/s", false, true});
  add_ranged_option(app, "--tick", a.tick_us, "locus tick, µs (at most 20 % of the head's τ)", kTickRange)
      ->capture_default_str();
  add_ranged_option(app, "--run-in", a.run_in_mm, "blanking run-in length, mm (default: sized by the head's settling)",
                    kExtensionRange);
  add_ranged_option(app, "--run-out", a.run_out_mm, "blanking run-out length, mm (default v·τ)", kExtensionRange);
  add_ranged_option(app, "--field", a.field_mm, "field size (square), mm", kFieldRange)->capture_default_str();
}

HeadAndPen make_head_and_pen(const PenArgs& a) {
  const auto head = find_head(a.head);
  if (!head) throw InputError("--head '" + a.head + "' is not one of SL10, SL14, cheap");
  HeadAndPen hp{*head, {}};
  hp.head.field_mm = a.field_mm;
  // The options' own ranges were checked while parsing; these depend on the head.
  const Range head_speeds{kSpeedRange.min, hp.head.max_speed_mm_s, "mm/s (head " + hp.head.name + "'s positioning limit)"};
  check_range("--speed", a.speed_mm_s, head_speeds);
  if (a.jump_speed_mm_s != 0) check_range("--jump-speed", a.jump_speed_mm_s, head_speeds);
  check_range("--tick", a.tick_us, Range{kMinTick_s * 1e6, hp.head.max_tick_s() * 1e6, "µs (20 % of the head's τ)"});
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
