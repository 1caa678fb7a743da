#pragma once
// A code's data as typed on a command line or in a job file. Literal by default; with escapes
// on, the control characters that DPM formats need (ANSI MH10.8.2 / ISO/IEC 15434 "[)>␞06␝…␄"
// on automotive and aerospace parts) can be written: \\ \n \r \t \0, \G (GS), \R (RS), \E (EOT)
// and \xHH — the names zint's escape mode uses.
#include <string>
#include <string_view>

namespace mark {

// Throws InputError naming the position of an unknown or incomplete escape.
std::string unescape_code_data(std::string_view text);

// The bytes with control characters shown as \xHH and a backslash doubled, for messages and
// text output (bytes from 0x80 up pass, so UTF-8 text reads as itself).
std::string printable_bytes(std::string_view bytes);

}  // namespace mark
