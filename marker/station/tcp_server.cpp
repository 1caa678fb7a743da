#include "marker/station/tcp_server.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>

#include "base/error.hpp"
#include "marker/limits/station_limits.hpp"
#include "marker/station/line_auth.hpp"
#include "marker/station/peer_allow.hpp"
#include "marker/station/station_commands.hpp"

namespace mark {

ListenAddress parse_host_port(const std::string& text, const std::string& option) {
  const std::size_t colon = text.rfind(':');
  if (colon == std::string::npos)
    throw InputError(option + " " + text + ": give HOST:PORT (e.g. 127.0.0.1:5555; port 0 picks a free one)");
  ListenAddress a;
  a.host = text.substr(0, colon);
  if (a.host.empty() || a.host == "localhost") a.host = "127.0.0.1";
  const std::string port = text.substr(colon + 1);
  const auto [end, ec] = std::from_chars(port.data(), port.data() + port.size(), a.port);
  if (port.empty() || ec != std::errc() || end != port.data() + port.size() || !kStationPortRange.contains(a.port))
    throw InputError(option + " " + text + ": the port must be a number in 0–65535");
  in_addr addr{};
  if (::inet_pton(AF_INET, a.host.c_str(), &addr) != 1)
    throw InputError(option + " " + text + ": the host must be an IPv4 address (127.0.0.1)");
  return a;
}

ListenAddress parse_listen_address(const std::string& text, const std::string& option, bool token_set) {
  ListenAddress a = parse_host_port(text, option);
  if (token_set) return a;
  in_addr addr{};
  ::inet_pton(AF_INET, a.host.c_str(), &addr);
  if ((ntohl(addr.s_addr) >> 24) != 127)
    throw InputError(option + " " + text +
                     ": only loopback addresses (127.0.0.0/8) for a station without a token: give --token FILE to "
                     "listen beyond loopback (a command that fires a laser must not come unauthenticated from the network)");
  return a;
}

namespace {

// The whole reply, or nothing more once the peer is gone (no SIGPIPE: MSG_NOSIGNAL).
bool send_line(int fd, std::string line) {
  line += '\n';
  std::size_t sent = 0;
  while (sent < line.size()) {
    const ssize_t n = ::send(fd, line.data() + sent, line.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    sent += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace

TcpServer::TcpServer(Station& station, const ListenAddress& address, int max_connections,
                     std::function<void(const std::string&)> log, std::string token)
    : station_(station), max_connections_(max_connections), log_(std::move(log)), token_(std::move(token)) {
  const std::string where = address.host + ":" + std::to_string(address.port);
  listen_fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (listen_fd_ < 0) throw InputError("--listen " + where + ": " + std::strerror(errno));
  const int one = 1;
  ::setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  sockaddr_in sa{};
  sa.sin_family = AF_INET;
  sa.sin_port = htons(static_cast<std::uint16_t>(address.port));
  ::inet_pton(AF_INET, address.host.c_str(), &sa.sin_addr);
  if (::bind(listen_fd_, reinterpret_cast<sockaddr*>(&sa), sizeof sa) != 0 || ::listen(listen_fd_, 16) != 0) {
    const std::string why = std::strerror(errno);
    ::close(listen_fd_);
    throw InputError("--listen " + where + ": cannot listen there: " + why);
  }
  socklen_t len = sizeof sa;
  ::getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&sa), &len);
  port_ = ntohs(sa.sin_port);
}

TcpServer::~TcpServer() { stop(); }

void TcpServer::serve(const std::function<bool()>& stop) {
  while (!stop()) {
    pollfd p{listen_fd_, POLLIN, 0};
    const int r = ::poll(&p, 1, 50);
    reap();
    if (r <= 0 || !(p.revents & POLLIN)) continue;
    sockaddr_in peer{};
    socklen_t peer_len = sizeof peer;
    const int fd = ::accept4(listen_fd_, reinterpret_cast<sockaddr*>(&peer), &peer_len, SOCK_CLOEXEC);
    if (fd < 0) continue;
    std::lock_guard lock(mutex_);
    if (static_cast<int>(connections_.size()) >= max_connections_) {
      send_line(fd, "ERR toomany the station takes at most " + std::to_string(max_connections_) +
                        " connections at a time; close one first");
      ::close(fd);
      log("connection refused: " + std::to_string(max_connections_) + " open already");
      continue;
    }
    auto c = std::make_unique<Connection>();
    c->fd = fd;
    c->peer = dotted(ntohl(peer.sin_addr.s_addr)) + ":" + std::to_string(ntohs(peer.sin_port));
    Connection& ref = *c;
    connections_.push_back(std::move(c));
    ref.thread = std::thread([this, &ref] { converse(ref); });
    log("connection opened (" + std::to_string(connections_.size()) + " open)");
  }
}

void TcpServer::converse(Connection& c) {
  LineAuth auth(token_);
  std::string buffer;
  bool skipping = false;  // the rest of an overlong line
  char chunk[1024];
  for (;;) {
    const ssize_t n = ::recv(c.fd, chunk, sizeof chunk, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    buffer.append(chunk, static_cast<std::size_t>(n));
    bool open = true;
    for (std::size_t nl; open && (nl = buffer.find('\n')) != std::string::npos;) {
      const std::string line = buffer.substr(0, nl);
      buffer.erase(0, nl + 1);
      if (skipping) {
        skipping = false;
        continue;
      }
      const LineAuth::Verdict v = auth.check(line);
      if (!v.log.empty()) log("auth: " + c.peer + ": " + v.log);
      open = send_line(c.fd, v.handled ? v.reply : station_command(station_, line)) && !v.close;
    }
    if (!open) break;
    if (!skipping && buffer.size() >= kStationLineMax) {
      // Answered once, when the line passes the limit; the rest up to its newline is dropped.
      skipping = true;
      buffer.clear();
      if (!send_line(c.fd, "ERR toolong a command line has at most " + std::to_string(kStationLineMax - 1) +
                               " bytes; the line was ignored"))
        break;
    }
    if (skipping) buffer.clear();
  }
  ::shutdown(c.fd, SHUT_RDWR);
  c.done.store(true, std::memory_order_release);
}

void TcpServer::reap() {
  std::lock_guard lock(mutex_);
  for (auto it = connections_.begin(); it != connections_.end();) {
    if (!(*it)->done.load(std::memory_order_acquire)) {
      ++it;
      continue;
    }
    (*it)->thread.join();
    ::close((*it)->fd);
    it = connections_.erase(it);
    log("connection closed (" + std::to_string(connections_.size()) + " open)");
  }
}

void TcpServer::stop() {
  if (listen_fd_ >= 0) {
    ::close(listen_fd_);
    listen_fd_ = -1;
  }
  {
    std::lock_guard lock(mutex_);
    for (auto& c : connections_) ::shutdown(c->fd, SHUT_RD);  // ends a blocked recv
  }
  for (;;) {
    std::unique_ptr<Connection> c;
    {
      std::lock_guard lock(mutex_);
      if (connections_.empty()) break;
      c = std::move(connections_.front());
      connections_.pop_front();
    }
    c->thread.join();
    ::close(c->fd);
  }
}

}  // namespace mark
