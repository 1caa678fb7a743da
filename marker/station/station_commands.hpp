#pragma once
// The station's one command set as text lines (docs/station.md): one ASCII command in, one
// reply line out, `OK ...` or `ERR <code> <message>`. The TCP line protocol sends these as
// they are; other interfaces call the Station directly with the same words.
#include <cstddef>
#include <string>
#include <string_view>

#include "marker/station/station.hpp"

namespace mark {

// The longest command line a client may send (bytes, the newline included).
inline constexpr std::size_t kStationLineMax = 4096;

// Executes one command line (without its newline; a trailing CR is ignored) and gives the
// reply line (without its newline). MARK runs the part on the caller's thread.
std::string station_command(Station& station, std::string_view line);

// A value in a reply, quoted when it has spaces, quotes, '=' or control characters
// (`"` and `\` escaped with `\`, a new line as \n).
std::string reply_value(std::string_view value);

// `id=12 outcome=done SN=1005 text="SN 1005"`: the part's fields on one line.
std::string part_reply(const PartResult& part);

}  // namespace mark
