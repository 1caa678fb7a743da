#pragma once
// What `marker serve` accepts (docs/station.md): every setting of the station with its range.
#include "marker/limits/value_range.hpp"

namespace mark {

// --max-connections: clients of the TCP line protocol at a time (one more gets ERR toomany).
inline const WholeRange kStationConnectionsRange{1, 64};
inline constexpr int kStationConnectionsDefault = 8;
// --listen's port (0: a free one, which the server logs).
inline const WholeRange kStationPortRange{0, 65535};
inline constexpr const char* kStationListenDefault = "127.0.0.1:5555";

}  // namespace mark
