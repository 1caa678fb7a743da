#include "marker/station/peer_allow.hpp"

#include <arpa/inet.h>

#include <charconv>

#include "base/error.hpp"

namespace mark {

AllowedNet parse_allowed_net(const std::string& text, const std::string& option) {
  const std::size_t slash = text.find('/');
  const std::string host = text.substr(0, slash);
  int bits = 32;
  if (slash != std::string::npos) {
    const std::string b = text.substr(slash + 1);
    const auto [end, ec] = std::from_chars(b.data(), b.data() + b.size(), bits);
    if (b.empty() || ec != std::errc() || end != b.data() + b.size() || bits < 0 || bits > 32)
      throw InputError(option + " " + text + ": the prefix length after / must be a number in 0–32");
  }
  in_addr addr{};
  if (::inet_pton(AF_INET, host.c_str(), &addr) != 1)
    throw InputError(option + " " + text + ": give an IPv4 address or network, ADDR[/BITS] (e.g. 192.168.10.0/24)");
  AllowedNet n;
  n.mask = bits == 0 ? 0 : ~std::uint32_t{0} << (32 - bits);
  n.net = ntohl(addr.s_addr) & n.mask;
  return n;
}

bool peer_allowed(const std::vector<AllowedNet>& allow, std::uint32_t peer) {
  if (peer == INADDR_LOOPBACK) return true;
  if (allow.empty()) return (peer >> 24) == 127;
  for (const AllowedNet& n : allow)
    if ((peer & n.mask) == n.net) return true;
  return false;
}

std::string dotted(std::uint32_t address) {
  return std::to_string(address >> 24) + "." + std::to_string(address >> 16 & 0xFF) + "." +
         std::to_string(address >> 8 & 0xFF) + "." + std::to_string(address & 0xFF);
}

}  // namespace mark
