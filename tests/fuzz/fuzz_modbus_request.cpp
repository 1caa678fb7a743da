// Fuzz target for the station's Modbus TCP interface (marker/station/modbus_server.hpp): the
// input is sent as raw bytes (one or more Modbus TCP frames, or garbage) to a ModbusServer on
// loopback (started once) over a station whose part source marks at once. Every answer must be
// a well-formed Modbus TCP frame: protocol id 0, its length field matching its bytes, and the
// function code of a request or that code with the exception bit (then one exception code the
// protocol defines). Also parse_coil_request on the input as a PDU, and --modbus-allow's parser
// on it as text: a write stays inside coils 0–2, an invalid request names exception 2 or 3, a
// parsed network has no host bits. Anything else, or a sanitizer report, is a bug.

#include <cstdint>
#include <string>

#include "base/error.hpp"
#include "fuzz_check.hpp"
#include "fuzz_loopback.hpp"
#include "fuzz_station_source.hpp"
#include "marker/station/modbus_map.hpp"
#include "marker/station/modbus_server.hpp"

using mark::fuzz::broken;

namespace {

struct Served {
  mark::fuzz::NullSource source;
  mark::Station station{source};
  mark::ModbusServer modbus{station, mark::parse_listen_address("127.0.0.1:0", "--modbus"), {}, 8};
};

Served& served() {
  static Served* s = new Served;  // lives for the process: libFuzzer exits without destructors
  return *s;
}

void check_parse(const std::uint8_t* data, std::size_t size) {
  const mark::CoilRequest r = mark::parse_coil_request(data, size);
  if (r.kind == mark::CoilRequest::write &&
      (r.values.empty() || r.first < 0 || r.first + static_cast<int>(r.values.size()) > mark::kCoilCount))
    broken("a coil write outside coils 0-2 accepted");
  if (r.kind == mark::CoilRequest::invalid && r.exception != mark::kExceptionIllegalAddress &&
      r.exception != mark::kExceptionIllegalValue)
    broken("an invalid request without exception 2 or 3");
  try {
    const mark::AllowedNet n = mark::parse_allowed_net(std::string(reinterpret_cast<const char*>(data), size),
                                                       "--modbus-allow");
    if ((n.net & ~n.mask) != 0) broken("a network with host bits set");
  } catch (const mark::InputError&) {
  }
}

void check_replies(const std::string& reply) {
  for (std::size_t at = 0; at < reply.size();) {
    if (reply.size() - at < 9) broken("a reply shorter than a Modbus TCP frame");
    const auto byte = [&](std::size_t i) { return static_cast<unsigned>(static_cast<unsigned char>(reply[at + i])); };
    if (byte(2) != 0 || byte(3) != 0) broken("a reply with a protocol id other than 0");
    const std::size_t length = byte(4) << 8 | byte(5);  // unit id onwards
    if (length < 3 || at + 6 + length > reply.size()) broken("a reply whose length field disagrees with its bytes");
    const unsigned function = byte(7);
    if (function & 0x80) {
      const unsigned code = byte(8);
      if (length != 3 || code < 1 || code > 11) broken("an exception reply with no protocol exception code");
    }
    at += 6 + length;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  check_parse(data, size);
  Served& s = served();
  const std::string reply = mark::fuzz::exchange_on_loopback(s.modbus.port(), data, size);
  s.station.wait_idle();
  check_replies(reply);
  return 0;
}
