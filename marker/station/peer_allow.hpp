#pragma once
// Which peers may talk to an unauthenticated interface (Modbus TCP has no authentication): an
// allow-list of IPv4 networks given as --modbus-allow ADDR[/BITS].
#include <cstdint>
#include <string>
#include <vector>

namespace mark {

struct AllowedNet {
  std::uint32_t net = 0;   // host byte order, the host bits cleared
  std::uint32_t mask = 0;  // host byte order
};

// "192.168.10.0/24", "10.1.2.3" (/32). Throws InputError naming `option` for a malformed
// address or BITS outside 0–32.
AllowedNet parse_allowed_net(const std::string& text, const std::string& option);

// 127.0.0.1 (the machine's own HMI) always; with no list, any loopback address (the listener is
// loopback then); with a list, an address in one of its networks.
bool peer_allowed(const std::vector<AllowedNet>& allow, std::uint32_t peer);

// Dotted quad of a host-order address, for the log.
std::string dotted(std::uint32_t address);

}  // namespace mark
