#include "marker/peen/plan_export.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "base/error.hpp"
#include "marker/output/output_file.hpp"
#include "marker/peen/gantry_run.hpp"

namespace mark {
namespace {

// Millimetres with four decimals: 0.1 µm, finer than any pin marker's step, so each position
// reads back to the step it came from.
constexpr int kMmDecimals = 4;

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  std::string s = buf;
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);  // no "-0.0"
  return s;
}

}  // namespace

void write_plan_csv(std::ostream& out, const PeenPlan& plan, const DotText& text,
                    const GantryConfig& gantry) {
  const GantryReport r = run_plan(plan, gantry, true);
  const int d = kMmDecimals;
  out << "seq,action,x_mm,y_mm,x_steps,y_steps,dot,character,move_s,arrive_s\n";
  const StepPoint home = to_steps(plan.home_mm, gantry);
  auto row = [&](std::size_t seq, const char* action, const StepPoint& at,
                 std::optional<std::size_t> dot, double move_s, double arrive_s) {
    const Point mm = to_mm(at, gantry);
    out << seq << ',' << action << ',' << fixed(mm.x(), d) << ',' << fixed(mm.y(), d) << ','
        << at.x << ',' << at.y << ',';
    if (dot) out << *dot << ',' << text.dots.at(*dot).character;
    else out << ',';
    out << ',' << fixed(move_s, 6) << ',' << fixed(arrive_s, 6) << '\n';
  };
  row(0, "home", home, std::nullopt, 0, 0);
  double t = 0;
  std::size_t seq = 1;
  for (std::size_t i = 0; i < r.log.size(); ++i) {
    const GantryMove& m = r.log[i];
    t += m.duration_s;
    const bool last = i + 1 == r.log.size() && !m.strike;
    row(seq++, m.strike ? "strike" : last ? "home" : "turn", m.to, m.strike, m.duration_s, t);
    if (m.strike) t += gantry.strike_s;
  }
}

void write_plan_gcode(std::ostream& out, const PeenPlan& plan, const DotText& text,
                      const GantryConfig& gantry) {
  const GantryReport r = run_plan(plan, gantry, true);
  const int d = kMmDecimals;
  out << "%\n"
      << "(marker peen: " << plan.planner << " planner, " << text.dots.size() << " dots, "
      << text.characters << " characters)\n"
      << "(simulated gantry time " << fixed(r.total_s, 3) << " s, travel " << fixed(r.travel_mm, 1)
      << " mm; strike = M64 P0, dwell, M65 P0)\n"
      << "G21 G90\n";
  auto go = [&](const StepPoint& at) {
    const Point mm = to_mm(at, gantry);
    out << "G0 X" << fixed(mm.x(), d) << " Y" << fixed(mm.y(), d) << '\n';
  };
  go(to_steps(plan.home_mm, gantry));
  for (const GantryMove& m : r.log) {
    if (!(m.to == m.from)) go(m.to);
    if (m.strike)
      out << "M64 P0\n"
          << "G4 P" << fixed(gantry.strike_s, 4) << '\n'
          << "M65 P0\n";
  }
  out << "M2\n%\n";
}

void export_plan(const std::string& path, const PeenPlan& plan, const DotText& text,
                 const GantryConfig& gantry) {
  const std::string ext = output_format(path, kPlanExtensions);  // "-": CSV to standard output
  if (std::find(kPlanExtensions.begin(), kPlanExtensions.end(), ext) == kPlanExtensions.end())
    throw InputError("output file '" + path + "': the name must end in .csv, .ngc, .nc or .gcode");
  std::ostringstream out;
  if (ext == ".csv") write_plan_csv(out, plan, text, gantry);
  else write_plan_gcode(out, plan, text, gantry);
  write_file_whole(path, out.str());
}

}  // namespace mark
