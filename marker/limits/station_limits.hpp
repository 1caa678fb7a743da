#pragma once
// The values inside the station's options and lines (docs/station.md): --listen's port and the
// line protocol's limits; the options themselves are declared in station_settings.hpp.
#include <string_view>

#include "marker/limits/value_range.hpp"

namespace mark {

// --listen's port (0: a free one, which the server logs).
inline constexpr WholeRange kStationPortRange{0, 65535};
inline constexpr std::string_view kStationListenDefault = "127.0.0.1:5555";

}  // namespace mark
