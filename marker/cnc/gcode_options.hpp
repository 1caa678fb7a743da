#pragma once
// How a toolpath is written as G-code: dialect, units and the program frame around the moves.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace mark {

enum class Dialect {
  linuxcnc,  // o<name> sub / call with parameters; rotation computed in the subprogram
  fanuc,     // O-number subprograms after M30, M98 P / M99, placed with G52; rotated letters inlined
  plain,     // grbl-compatible: no subprograms, no G90.1/G91.1, everything inlined
};

enum class Units { mm, inch };

// What one line of a program may hold in each dialect; the writer never writes a longer one.
//   linuxcnc: 252 characters (LinuxCNC 2.9's rs274 reads 252 and refuses 253 with "Command too
//             long"; measured with Debian's linuxcnc-uspace, tests/marker/cnc/gcode_writer_test.cpp).
//   fanuc:    128 characters per block, and 31 for the program name on the O line: what the
//             smallest Fanuc-style controls accept (Fanuc shows 31 characters of a program name).
//   plain:    79 characters: grbl's line buffer holds 80 bytes with the terminator (error 11,
//             "Max characters per line exceeded"); a sender that counts characters streams the
//             whole line, comments included, so the whole line stays within it.
struct DialectLimits {
  std::size_t line_chars = 0;
  std::size_t program_name_chars = 0;  // fanuc: inside the O line's comment; 0 where there is none
};
DialectLimits dialect_limits(Dialect dialect);
std::string_view to_string(Dialect dialect);

struct GcodeOptions {
  Dialect dialect = Dialect::linuxcnc;
  Units units = Units::mm;
  // Comment at the top of the program: one comment line per line of the title, wrapped to the
  // dialect's line length (never cut short).
  std::string title;
  std::vector<std::string> header;   // user lines after the modal preamble
  std::vector<std::string> footer;   // user lines before the program end
  double spindle_rpm = 10000;        // 0: no spindle commands (M3/M5)
  bool end_with_m30 = true;          // M30 (end and rewind) or M2
  int program_number = 1;            // fanuc: O number of the main program
  int first_subprogram_number = 1001;  // fanuc: O number of the first subprogram
};

// Throws InputError for lines that would break the program (newlines, a '%', longer than the
// dialect's line), and program numbers outside O1..O9999.
void validate(const GcodeOptions& options);

Dialect parse_dialect(const std::string& name);  // "linuxcnc" | "fanuc" | "plain"
Units parse_units(const std::string& name);      // "mm" | "inch"

}  // namespace mark
