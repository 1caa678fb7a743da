#pragma once
// A needle path for the machine: as a move/strike list (CSV) or as G-code for stepper
// controllers. Both come from the simulated run, so positions are the gantry's whole steps.
//
// CSV, one row per arrival, the first at home before anything moves:
//   seq,action,x_mm,y_mm,x_steps,y_steps,dot,character,move_s,arrive_s
// action is home | strike | turn; dot and character are empty unless a dot is struck; move_s is
// the move that ends at this row, arrive_s the time at arrival (strikes before it included).
//
// G-code (RS-274, LinuxCNC dialect): G21 G90, every position a rapid G0 at the machine's own
// speed and acceleration (what the time model assumes), every strike
//   M64 P0 / G4 P<strike_s> / M65 P0
// — digital output 0 fires the pin for the strike time, then releases it. Ends with M2.
#include <initializer_list>
#include <ostream>
#include <string>
#include <string_view>

#include "marker/peen/dot_text.hpp"
#include "marker/peen/gantry.hpp"
#include "marker/peen/peen_plan.hpp"

namespace mark {

void write_plan_csv(std::ostream& out, const PeenPlan& plan, const DotText& text,
                    const GantryConfig& gantry);
void write_plan_gcode(std::ostream& out, const PeenPlan& plan, const DotText& text,
                      const GantryConfig& gantry);

// The extensions export_plan writes.
inline const std::initializer_list<std::string_view> kPlanExtensions = {".csv", ".ngc", ".nc", ".gcode"};

// By the file's extension: .csv, or .ngc / .nc / .gcode, written whole (output_file.hpp). Throws
// InputError naming the file for another extension or when it cannot be written.
void export_plan(const std::string& path, const PeenPlan& plan, const DotText& text,
                 const GantryConfig& gantry);

}  // namespace mark
