#pragma once
// The station fuzz targets' client: the input sent as it is to a server on 127.0.0.1:`port`,
// the sending side shut, and everything the server answered until it closed (5 s at most).
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string>

#include "fuzz_check.hpp"

namespace mark::fuzz {

[[noreturn]] inline void broken_errno(const char* what) {
  static std::string said;
  said = std::string(what) + ": " + std::strerror(errno);
  broken(said.c_str());
}

inline std::string exchange_on_loopback(int port, const void* data, std::size_t size) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) broken("cannot open a socket");
  // Each exchange ends with this side in TIME_WAIT for 60 s (it sends its FIN first, to say the
  // input is over), holding a local port. At ~2500 inputs a second one source address's ~28 k
  // ephemeral ports run out within 12 s where the kernel does not reuse TIME_WAIT ports
  // (net.ipv4.tcp_tw_reuse=0, as on CI machines): connect then fails with EADDRNOTAVAIL, a
  // failure of the fuzzer, not of the server. So the source address turns through 127.0.1.0/24:
  // every one has its own port range, and the server sees them all as loopback.
  static std::uint32_t turn = 0;
  sockaddr_in from{};
  from.sin_family = AF_INET;
  from.sin_addr.s_addr = htonl((127u << 24) | (1u << 8) | (turn++ % 254u + 1u));
  const int late_port = 1;  // the port is picked at connect, where the whole 4-tuple is known
  ::setsockopt(fd, IPPROTO_IP, IP_BIND_ADDRESS_NO_PORT, &late_port, sizeof late_port);
  if (::bind(fd, reinterpret_cast<sockaddr*>(&from), sizeof from) != 0) broken_errno("cannot bind a loopback source address");
  sockaddr_in sa{};
  sa.sin_family = AF_INET;
  sa.sin_port = htons(static_cast<std::uint16_t>(port));
  ::inet_pton(AF_INET, "127.0.0.1", &sa.sin_addr);
  // libFuzzer's timer signal may interrupt a blocking call: a connect then goes on by itself
  // (wait until the socket is writable and read its result), a send or recv is repeated.
  if (::connect(fd, reinterpret_cast<sockaddr*>(&sa), sizeof sa) != 0) {
    if (errno != EINTR) broken_errno("cannot connect to the server");
    pollfd p{fd, POLLOUT, 0};
    while (::poll(&p, 1, 5000) < 0 && errno == EINTR) {
    }
    int error = 0;
    socklen_t len = sizeof error;
    ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &len);
    if (error != 0) {
      errno = error;
      broken_errno("cannot connect to the server");
    }
  }
  timeval tv{5, 0};
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  const char* bytes = static_cast<const char*>(data);
  for (std::size_t sent = 0; sent < size;) {
    const ssize_t n = ::send(fd, bytes + sent, size - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // the server closed early (a bad frame, a body over the limit): its answer is read below
    sent += static_cast<std::size_t>(n);
  }
  ::shutdown(fd, SHUT_WR);
  std::string reply;
  char chunk[4096];
  for (ssize_t n; (n = ::recv(fd, chunk, sizeof chunk, 0)) > 0 || (n < 0 && errno == EINTR);)
    if (n > 0) reply.append(chunk, static_cast<std::size_t>(n));
  ::close(fd);
  return reply;
}

}  // namespace mark::fuzz
