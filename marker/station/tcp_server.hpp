#pragma once
// The station's TCP line protocol (docs/station.md): one ASCII command per line, one reply
// line each (station_commands.hpp). A thread per connection, at most `max_connections` at a
// time: one more gets `ERR toomany ...` and is closed, changing nothing. A line longer than
// kStationLineMax gets `ERR toolong ...` and is skipped to its end. A client that goes away
// mid-MARK does not stop the mark: the part ends and is recorded; only its reply is lost.
#include <atomic>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "marker/station/station.hpp"

namespace mark {

// An address to listen on, loopback only unless the station has a token (--token): a station
// that can fire a laser must not take commands from the network unauthenticated.
struct ListenAddress {
  std::string host;  // dotted IPv4 (127.x.x.x without a token)
  int port = 0;      // 0: a free port (the server says which)
};

// "127.0.0.1:5555", "localhost:0", ":5555" (127.0.0.1). Throws InputError naming `option`, for a
// malformed address, a port outside 0–65535, or, unless `token_set`, an address that is not
// loopback.
ListenAddress parse_listen_address(const std::string& text, const std::string& option, bool token_set = false);
// The same for any IPv4 address (0.0.0.0, a plant network's): for an interface that guards
// its peers otherwise (Modbus's --modbus-allow).
ListenAddress parse_host_port(const std::string& text, const std::string& option);

class TcpServer {
 public:
  // Binds and listens now (throws InputError naming the address when it cannot). A non-empty
  // `token` (station_token.hpp): every session must AUTH first (line_auth.hpp).
  TcpServer(Station& station, const ListenAddress& address, int max_connections,
            std::function<void(const std::string&)> log = {}, std::string token = {});
  ~TcpServer();  // stop()
  TcpServer(const TcpServer&) = delete;
  TcpServer& operator=(const TcpServer&) = delete;

  int port() const { return port_; }
  // Accepts connections until `stop` returns true (polled every 50 ms).
  void serve(const std::function<bool()>& stop);
  // Closes the listening socket, ends every connection's read and joins its thread (a MARK in
  // progress on one finishes first: abort the station before to end it sooner).
  void stop();

 private:
  struct Connection {
    int fd = -1;
    std::string peer;  // "ADDR:PORT", for the log
    std::thread thread;
    std::atomic<bool> done{false};
  };
  void converse(Connection& c);
  void reap();  // joins connections that ended
  void log(const std::string& line) const {
    if (log_) log_(line);
  }

  Station& station_;
  int max_connections_;
  std::function<void(const std::string&)> log_;
  std::string token_;
  int listen_fd_ = -1;
  int port_ = 0;
  std::mutex mutex_;
  std::list<std::unique_ptr<Connection>> connections_;
};

}  // namespace mark
