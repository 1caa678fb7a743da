#include "marker/store/utc_time.hpp"

#include <date/date.h>

#include <charconv>
#include <cstdio>

namespace mark {

using namespace std::chrono;

std::string format_utc(SysTime t) { return date::format("%Y-%m-%dT%H:%M:%SZ", t); }

std::optional<SysTime> parse_since(std::string_view text, SysTime now) {
  if (text.empty()) return std::nullopt;
  const char unit = text.back();
  if (unit == 's' || unit == 'm' || unit == 'h' || unit == 'd') {
    long long n = 0;
    const char* end = text.data() + text.size() - 1;
    const auto [p, ec] = std::from_chars(text.data(), end, n);
    if (ec == std::errc{} && p == end && n >= 0 && n < 1'000'000'000LL) {
      const long long s = n * (unit == 's' ? 1 : unit == 'm' ? 60 : unit == 'h' ? 3600 : 86400);
      return now - seconds{s};
    }
    if (unit != 'Z') return std::nullopt;
  }
  std::string s(text);
  if (s.size() > 10 && s[10] == ' ') s[10] = 'T';
  if (!s.empty() && s.back() == 'Z') s.pop_back();
  // YYYY-MM-DD[THH:MM[:SS[.ffffff]]], checked field by field (no locale, no stream state).
  int y = 0, mo = 0, d = 0, h = 0, mi = 0, n = 0;
  double sec = 0;
  if (std::sscanf(s.c_str(), "%4d-%2d-%2d%n", &y, &mo, &d, &n) != 3 || n != 10) return std::nullopt;
  if (s.size() > 10) {
    int m = 0;
    if (std::sscanf(s.c_str() + 10, "T%2d:%2d%n", &h, &mi, &m) != 2 || m != 6) return std::nullopt;
    if (s.size() > 16) {
      int k = 0;
      if (s[16] != ':' || std::sscanf(s.c_str() + 17, "%lf%n", &sec, &k) != 1 ||
          17 + static_cast<std::size_t>(k) != s.size() || !(sec >= 0 && sec < 61))
        return std::nullopt;
    }
  }
  const date::year_month_day ymd{date::year{y}, date::month{static_cast<unsigned>(mo)},
                                 date::day{static_cast<unsigned>(d)}};
  if (!ymd.ok() || h > 23 || mi > 59 || h < 0 || mi < 0) return std::nullopt;
  return SysTime{date::sys_days{ymd}} + hours{h} + minutes{mi} +
         microseconds{static_cast<long long>(sec * 1e6 + 0.5)};
  return std::nullopt;
}

}  // namespace mark
