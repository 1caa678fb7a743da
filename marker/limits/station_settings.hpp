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

// Board I/O (docs/station.md "Board I/O"): the LMC board's own input and output pins.
inline constexpr Text kTrigger{
    {"--trigger", "", "lmc-input:BIT: a rising edge on the LMC board's input pin BIT (0 to 15) starts one mark; --device lmc or lmc-emulated"},
    {},
    "off"};
inline constexpr Text kSignal{
    {"--signal", "", "ready=BIT,busy=BIT,done=BIT,error=BIT (any of them, bits 0 to 15, each once): the station's state on the LMC board's output pins"},
    {},
    "off"};
inline constexpr Quantity kTriggerDebounce{
    {"--trigger-debounce-ms", "", "--trigger: the input counts as changed once it held the new level this long"},
    {0, 1000, "ms"},
    5};
inline constexpr Quantity kTriggerMinPulse{
    {"--trigger-min-pulse-ms", "", "--trigger: a rising edge marks once the input stayed high this long (shorter pulses mark nothing)"},
    {0, 1000, "ms"},
    5};

inline constexpr SettingRef kStationSettingList[] = {&kListen,  &kHttp,   &kModbus,          &kModbusAllow, &kToken, &kMaxConnections,
                                                     &kTrigger, &kSignal, &kTriggerDebounce, &kTriggerMinPulse};
inline constexpr SettingTable kStationSettings{"station", "Station", "", kStationSettingList};

}  // namespace mark
