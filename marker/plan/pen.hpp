#pragma once
// A pen: how the planner turns lit elements into commands — speeds, the tick of the locus,
// which corner strategy to use and its parameters, and the laser delay line's edge delays.
// Defaults come from the head's tracking error τ (dynamics.md §2.2 and §3.2).
#include <cstdint>
#include <string_view>

namespace mark {

enum class CornerStrategy {
  blanking,  // the seed's claim: laser-off run-out, join and run-in lines at sharp corners and
             // at every stroke's start and end; the laser bit delayed by τ against the mirrors
  delays,    // the RTC model: laser-on/off delays, jump, mark and polygon delays
  none       // neither (for comparison)
};

std::string_view to_string(CornerStrategy strategy);
// "blanking", "delays" or "none"; throws InputError naming the value otherwise.
CornerStrategy parse_corner_strategy(std::string_view name);

struct Pen {
  double mark_speed_mm_s = 1000;
  double jump_speed_mm_s = 5000;
  double tick_s = 10e-6;
  CornerStrategy corner = CornerStrategy::blanking;

  // Laser delay line (every strategy): laser-on edges and laser-off edges leave the line memory
  // this much later than the coordinates they came with.
  double laser_on_delay_s = 0;
  double laser_off_delay_s = 0;

  // Scanner delays (strategy `delays`), dwells of the mirrors.
  double jump_delay_s = 0;     // after every jump
  double mark_delay_s = 0;     // after the last mark of a stroke
  double polygon_delay_s = 0;  // between two marks of a stroke, × (1 − cos φ)

  // Blanking (strategy `blanking`).
  double blank_angle_deg = 0;  // lit corners turning by more than this get blanking lines
  double run_in_mm = 0;        // the backward extension before every lit element's start
  double run_out_mm = 0;       // the forward extension after every lit element's end
  double join_speed_mm_s = 0;  // speed on the joining line between a run-out and a run-in

  // Seconds → whole ticks of this pen (rounded to nearest).
  std::uint32_t ticks(double seconds) const;
};

// The multiples of v·τ and of τ the defaults are built from. The blanking lengths were chosen
// with the simulated scanner (see tests/marker/blanking_tuning_test.cpp and the issue note).
struct PenRules {
  // RTC starting rule (SCANLAB manuals, §6.1 of every head manual).
  double laser_on = 0.6, laser_off = 1.2, jump = 2.0, mark = 1.0, polygon = 0.5;
  // Blanking: extension lengths as multiples of v·τ; the joining line at jump speed.
  double run_in = 3.0, run_out = 1.5;
  // Corners turning less than this stay lit (the lag's corner cut there is below a few µm at
  // marking speeds where the rest of the figure keeps its quality).
  double blank_angle_deg = 8.0;
};

// A pen for a head with tracking error `tracking_error_s`, every parameter from the rules.
Pen default_pen(CornerStrategy strategy, double tracking_error_s, double mark_speed_mm_s,
                double jump_speed_mm_s, double tick_s = 10e-6, const PenRules& rules = {});

}  // namespace mark
