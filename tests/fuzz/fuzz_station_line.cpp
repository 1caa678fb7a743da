// Fuzz target for the station's command lines (marker/station/station_commands.hpp) and the
// --listen address: any line gets exactly one reply line, `OK…` or `ERR <code> <message>`, with
// no newline in it, against a part source that records what it was asked; --listen either
// parses to a loopback address and a port in 0–65535 or throws InputError. Anything else is a bug.
#include <cstdint>
#include <string>
#include <string_view>

#include "base/error.hpp"
#include "fuzz_check.hpp"
#include "fuzz_station_source.hpp"
#include "marker/station/station_commands.hpp"
#include "marker/station/tcp_server.hpp"

using mark::fuzz::broken;
using mark::fuzz::NullSource;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  NullSource source;
  mark::Station station(source);
  const std::string reply = mark::station_command(station, text);
  if (reply.find('\n') != std::string::npos || reply.find('\r') != std::string::npos) broken("a reply with a line break");
  if (reply != "OK" && reply.rfind("OK ", 0) != 0 && reply.rfind("ERR ", 0) != 0) broken("a reply neither OK nor ERR");
  station.wait_idle();
  try {
    const mark::ListenAddress a = mark::parse_listen_address(std::string(text), "--listen");
    if (a.port < 0 || a.port > 65535 || a.host.rfind("127.", 0) != 0) broken("a non-loopback address or bad port accepted");
  } catch (const mark::InputError&) {
  }
  return 0;
}
