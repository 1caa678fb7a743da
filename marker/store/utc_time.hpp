#pragma once
// Instants in the audit log: ISO 8601 in UTC with microseconds ("2026-03-05T09:41:00.000000Z"),
// so text order is time order in both store backends.
#include <optional>
#include <string>
#include <string_view>

#include "marker/vars/clock.hpp"

namespace mark {

std::string format_utc(SysTime t);
// "2026-03-05", "2026-03-05T09:41", "2026-03-05T09:41:07[.123456][Z]" (UTC; a space may stand
// for the T), or a span back from `now`: "90s", "30m", "12h", "7d". Nothing when malformed.
std::optional<SysTime> parse_since(std::string_view text, SysTime now);

}  // namespace mark
