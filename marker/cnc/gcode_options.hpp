#pragma once
// How a toolpath is written as G-code: dialect, units and the program frame around the moves.
#include <string>
#include <vector>

namespace mark {

enum class Dialect {
  linuxcnc,  // o<name> sub / call with parameters; rotation computed in the subprogram
  fanuc,     // O-number subprograms after M30, M98 P / M99, placed with G52; rotated letters inlined
  plain,     // grbl-compatible: no subprograms, no G90.1/G91.1, everything inlined
};

enum class Units { mm, inch };

struct GcodeOptions {
  Dialect dialect = Dialect::linuxcnc;
  Units units = Units::mm;
  std::string title;                 // comment at the top of the program
  std::vector<std::string> header;   // user lines after the modal preamble
  std::vector<std::string> footer;   // user lines before the program end
  double spindle_rpm = 10000;        // 0: no spindle commands (M3/M5)
  bool end_with_m30 = true;          // M30 (end and rewind) or M2
  int program_number = 1;            // fanuc: O number of the main program
  int first_subprogram_number = 1001;  // fanuc: O number of the first subprogram
};

// Throws InputError for lines that would break the program (newlines, a '%'), and program
// numbers outside O1..O9999.
void validate(const GcodeOptions& options);

Dialect parse_dialect(const std::string& name);  // "linuxcnc" | "fanuc" | "plain"
Units parse_units(const std::string& name);      // "mm" | "inch"

}  // namespace mark
