#pragma once
// The settings of the marking station (`marker serve`, docs/station.md), one declaration each
// (setting.hpp). The job's own (--device, --set, --station, --create-counters, --virtual-time and
// the store's) are the tables that `marker mark --job` takes them from.
#include "marker/limits/setting.hpp"
#include "marker/limits/station_limits.hpp"

namespace mark {

inline constexpr Text kListen{
    {"--listen", "", "TCP line protocol on HOST:PORT, loopback only unless --token (port 0: a free one, logged)"},
    kStationListenDefault};
inline constexpr Text kHttp{
    {"--http", "", "HTTP + JSON, event stream and operator page on HOST:PORT, loopback only unless --token (port 0: a free one, logged)"},
    {},
    "off"};
inline constexpr Text kModbus{
    {"--modbus", "", "Modbus TCP register map on HOST:PORT (port 0: a free one, logged); beyond loopback it needs --modbus-allow"},
    {},
    "off"};
inline constexpr Text kModbusAllow{
    {"--modbus-allow", "", "--modbus: an IPv4 ADDR[/BITS] whose clients may connect (repeatable); others are closed unread"},
    {},
    "127.0.0.1 only (loopback when no list)"};
inline constexpr Text kToken{
    {"--token", "", "a file (mode 600) whose first line is the token every TCP session (AUTH) and HTTP API request (Bearer) must give; allows any --listen/--http address"},
    {},
    "none (loopback only, no authentication)"};
inline constexpr Count kMaxConnections{
    {"--max-connections", "", "TCP clients at a time, and Modbus clients (one more gets ERR toomany / is closed)"}, {1, 64}, 8};

inline constexpr SettingRef kStationSettingList[] = {&kListen, &kHttp, &kModbus, &kModbusAllow, &kToken, &kMaxConnections};
inline constexpr SettingTable kStationSettings{"station", "Station", "", kStationSettingList};

}  // namespace mark
