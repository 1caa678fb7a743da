#pragma once
// The settings of the marking station (`marker serve`, docs/station.md), one declaration each
// (setting.hpp). The job's own (--device, --set, --station, --create-counters, --virtual-time and
// the store's) are the tables that `marker mark --job` takes them from.
#include "marker/limits/setting.hpp"
#include "marker/limits/station_limits.hpp"

namespace mark {

inline constexpr Text kListen{
    {"--listen", "", "TCP line protocol on HOST:PORT, loopback only (port 0: a free one, logged)"},
    kStationListenDefault};
inline constexpr Text kHttp{
    {"--http", "", "HTTP + JSON, event stream and operator page on HOST:PORT, loopback only (port 0: a free one, logged)"},
    {},
    "off"};
inline constexpr Count kMaxConnections{
    {"--max-connections", "", "TCP clients at a time (one more gets ERR toomany)"}, {1, 64}, 8};

inline constexpr SettingRef kStationSettingList[] = {&kListen, &kHttp, &kMaxConnections};
inline constexpr SettingTable kStationSettings{"station", "Station", "", kStationSettingList};

}  // namespace mark
