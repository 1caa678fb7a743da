#pragma once
// The station's HTTP + JSON interface (docs/station.md, "HTTP"): REST endpoints that are thin
// adapters over the same Station calls as the TCP line protocol, a server-sent event stream of
// state changes and parts (GET /api/events) and the operator page (GET /). cpp-httplib is large:
// only http_server.cpp includes it, behind this header.
#include <functional>
#include <memory>
#include <string>

#include "marker/station/station.hpp"
#include "marker/station/tcp_server.hpp"

namespace mark {

// The largest request body the server reads (PUT /api/vars/NAME's value is far smaller); a
// larger one gets 413 and changes nothing.
inline constexpr std::size_t kHttpBodyMax = 64 * 1024;

class HttpServer {
 public:
  // Binds now (throws InputError naming `--http` and the address when it cannot) and serves on
  // threads of its own until stop(). `station` outlives the server. A non-empty `token`
  // (station_token.hpp): every /api/ request must carry `Authorization: Bearer <token>`, or it
  // gets 401 and nothing runs; the operator page (static, no data) is served to anyone.
  HttpServer(Station& station, const ListenAddress& address, std::function<void(const std::string&)> log = {},
             std::string token = {});
  ~HttpServer();  // stop()
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  int port() const;
  // Ends every event stream, stops listening and joins the server's threads (a POST /api/mark
  // in progress finishes first: abort the station before to end it sooner).
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mark
