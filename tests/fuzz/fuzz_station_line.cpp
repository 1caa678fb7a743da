// Fuzz target for the station's command lines (marker/station/station_commands.hpp), a TCP
// session's authentication (line_auth.hpp) and the --listen address: any line gets exactly one
// reply line, `OK…` or `ERR <code> <message>`, with no newline in it, against a part source
// that records what it was asked. The input's lines, sent as one session to a station with a
// token, never reach the station before an `AUTH <the token>` answered `OK auth` (the source is
// asked nothing, a refused line's reply is `ERR auth …`), and the session ends after 3 wrong
// tokens. --listen either parses to a loopback address (any IPv4 with a token) and a port in
// 0–65535 or throws InputError. Anything else is a bug.
#include <cstdint>
#include <string>
#include <string_view>

#include "base/error.hpp"
#include "fuzz_check.hpp"
#include "fuzz_station_source.hpp"
#include "marker/station/line_auth.hpp"
#include "marker/station/station_commands.hpp"
#include "marker/station/tcp_server.hpp"

using mark::fuzz::broken;
using mark::fuzz::NullSource;

namespace {

constexpr std::string_view kToken = "fuzz-token-0123456789";  // seeds/station_line holds it

void check_reply(const std::string& reply) {
  if (reply.find('\n') != std::string::npos || reply.find('\r') != std::string::npos) broken("a reply with a line break");
  if (reply != "OK" && reply.rfind("OK ", 0) != 0 && reply.rfind("ERR ", 0) != 0) broken("a reply neither OK nor ERR");
}

// The input's lines as one session with a token set.
void session(std::string_view text) {
  NullSource source;
  mark::Station station(source);
  mark::LineAuth auth{std::string(kToken)};
  int wrong = 0;
  for (std::size_t from = 0; from <= text.size();) {
    const std::size_t nl = std::min(text.find('\n', from), text.size());
    std::string_view line = text.substr(from, nl - from);
    from = nl + 1;
    const bool was_authenticated = auth.authenticated();
    const int asked = source.asked;
    const mark::LineAuth::Verdict v = auth.check(line);
    if (v.handled) {
      check_reply(v.reply);
      if (source.asked != asked) broken("the station was asked something while AUTH was checked");
      if (v.log.find(kToken) != std::string::npos) broken("the token in the log");
      if (v.reply == "OK auth") {
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        if (line.size() != 5 + kToken.size() || line.substr(5) != kToken) broken("OK auth for a wrong token");
        wrong = 0;
      } else if (v.reply.rfind("ERR auth wrong token", 0) == 0) {
        ++wrong;
      } else if (v.reply.rfind("ERR auth ", 0) != 0) {
        broken("a refused line answered other than ERR auth");
      }
      if (v.close != (wrong >= mark::kAuthTriesMax)) broken("the session closed at the wrong count of wrong tokens");
      if (v.close) break;
      continue;
    }
    if (!was_authenticated) broken("a line reached the station before a right AUTH");
    check_reply(mark::station_command(station, line));
  }
  station.wait_idle();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  {
    NullSource source;
    mark::Station station(source);
    check_reply(mark::station_command(station, text));
    station.wait_idle();
  }
  session(text);
  for (const bool token : {false, true}) {
    try {
      const mark::ListenAddress a = mark::parse_listen_address(std::string(text), "--listen", token);
      if (a.port < 0 || a.port > 65535) broken("a bad port accepted");
      if (!token && a.host.rfind("127.", 0) != 0) broken("a non-loopback address accepted without a token");
    } catch (const mark::InputError&) {
    }
  }
  return 0;
}
