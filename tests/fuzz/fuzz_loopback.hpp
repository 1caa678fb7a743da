#pragma once
// The station fuzz targets' client: the input sent as it is to a server on 127.0.0.1:`port`,
// the sending side shut, and everything the server answered until it closed (5 s at most).
#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <cstdint>
#include <string>

#include "fuzz_check.hpp"

namespace mark::fuzz {

inline std::string exchange_on_loopback(int port, const void* data, std::size_t size) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in sa{};
  sa.sin_family = AF_INET;
  sa.sin_port = htons(static_cast<std::uint16_t>(port));
  ::inet_pton(AF_INET, "127.0.0.1", &sa.sin_addr);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&sa), sizeof sa) != 0) broken("cannot connect to the server");
  timeval tv{5, 0};
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  // Closed with a reset, not through TIME_WAIT: at ~2000 inputs a second every exchange would
  // otherwise hold a local port for 60 s, and after ~28 k of them (the kernel's ephemeral range)
  // connect fails with EADDRNOTAVAIL — a failure of the fuzzer, not of the server. The reply has
  // been read to its end before the close, so nothing is lost.
  const linger reset{1, 0};
  ::setsockopt(fd, SOL_SOCKET, SO_LINGER, &reset, sizeof reset);
  const char* bytes = static_cast<const char*>(data);
  for (std::size_t sent = 0; sent < size;) {
    const ssize_t n = ::send(fd, bytes + sent, size - sent, MSG_NOSIGNAL);
    if (n <= 0) break;  // the server closed early (a bad frame, a body over the limit): its answer is read below
    sent += static_cast<std::size_t>(n);
  }
  ::shutdown(fd, SHUT_WR);
  std::string reply;
  char chunk[4096];
  for (ssize_t n; (n = ::recv(fd, chunk, sizeof chunk, 0)) > 0;) reply.append(chunk, static_cast<std::size_t>(n));
  ::close(fd);
  return reply;
}

}  // namespace mark::fuzz
