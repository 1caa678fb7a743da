#include "marker/station/http_server.hpp"

#include <sys/socket.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <optional>
#include <thread>

#include "base/error.hpp"
#include "marker/production/part_json.hpp"
#include "marker/station/event_stream.hpp"
#include "marker/station/operator_page.hpp"
#include "marker/station/station_json.hpp"
#include "marker/station/station_token.hpp"
#include "marker/store/audit_format.hpp"
// Last: it brings <resolv.h>, whose `_res` macro breaks Eigen's headers included after it.
#include <httplib.h>

namespace mark {
namespace {

using nlohmann::json;

// GET /api/log's rows per request: the whole answer is built in memory, so it is bounded.
constexpr long long kLogRowsMax = 10'000;
constexpr long long kLogRowsDefault = 50;
// Threads serving requests: each open event stream holds one, a waiting POST /api/mark another.
constexpr std::size_t kHttpThreads = 16;

void reply(httplib::Response& res, int status, const json& body) {
  res.status = status;
  res.set_content(json_text(body), "application/json");
}

void refuse(httplib::Response& res, const StationError& e) { reply(res, http_status(e.code), error_json(e)); }

void bad_request(httplib::Response& res, std::string message) {
  refuse(res, StationError{"syntax", std::move(message)});
}

constexpr const char* kEndpoints =
    "GET /api/status, POST /api/mark[?async=1], POST /api/abort, POST /api/pause, POST /api/resume, "
    "POST /api/reset, PUT /api/vars/NAME, GET /api/serial/NAME, GET /api/preview, GET /api/preview.png, GET /api/log?limit=N, "
    "GET /api/events, GET /";

// A body a verb without arguments accepts: nothing, or an empty JSON object.
bool empty_body(const std::string& body) {
  if (body.find_first_not_of(" \t\r\n") == std::string::npos) return true;
  const json j = json::parse(body, nullptr, false);
  return j.is_object() && j.empty();
}

// Why a request is refused without the right `Authorization: Bearer <token>`; nullopt: it may
// run. The reason never echoes what was given.
std::optional<std::string> bearer_refusal(const httplib::Request& req, const std::string& token) {
  if (!req.has_header("Authorization"))
    return "this station needs a token: send Authorization: Bearer <token> (marker serve --token)";
  const std::string header = req.get_header_value("Authorization");
  constexpr std::string_view kScheme = "Bearer ";
  if (header.size() < kScheme.size() || !std::equal(kScheme.begin(), kScheme.end(), header.begin(), [](char a, char b) {
        return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
      }))
    return "the Authorization header must be Bearer <token>";
  std::string_view given(header);
  given.remove_prefix(kScheme.size());
  while (!given.empty() && given.front() == ' ') given.remove_prefix(1);
  if (!token_matches(token, given)) return "wrong token";
  return std::nullopt;
}

}  // namespace

struct HttpServer::Impl {
  Station& station;
  std::function<void(const std::string&)> log;
  // Shared with the station's listener, which may outlive the server (a part ending after stop).
  std::shared_ptr<EventStream> events = std::make_shared<EventStream>();
  // Event streams being sent: stop() lets them end (their last events out) before it stops.
  std::shared_ptr<std::atomic<int>> open_streams = std::make_shared<std::atomic<int>>(0);
  httplib::Server server;
  std::thread thread;
  int port = 0;

  Impl(Station& s, std::function<void(const std::string&)> l) : station(s), log(std::move(l)) {}
  void routes();
  void stream_events(httplib::Response& res);
};

void HttpServer::Impl::routes() {
  Station& st = station;
  server.Get("/api/status", [&st](const httplib::Request&, httplib::Response& res) {
    reply(res, 200, status_json(st.status()));
  });
  server.Post("/api/mark", [&st](const httplib::Request& req, httplib::Response& res) {
    if (!empty_body(req.body))
      return bad_request(res, "POST /api/mark takes no body (set variables first with PUT /api/vars/NAME)");
    if (req.has_param("async")) {
      if (req.get_param_value("async") != "1") return bad_request(res, "POST /api/mark: async takes 1 (?async=1)");
      if (auto e = st.mark_async()) return refuse(res, *e);
      return reply(res, 202, {{"started", true}});
    }
    const MarkAttempt a = st.mark();
    if (!a.part) return refuse(res, *a.error);
    json body = part_line(*a.part);
    if (a.part->good()) return reply(res, 200, body);
    // The part ran and is recorded, but did not end done: the status says how, the body is the part.
    const std::string outcome(a.part->outcome_name());
    body["error"] = a.part->message.empty() ? "the part ended " + outcome : a.part->message;
    reply(res, http_status(outcome), body);
  });
  server.Post("/api/abort", [&st](const httplib::Request&, httplib::Response& res) {
    reply(res, 200, {{"laser_off", true}, {"state_was", to_string(st.abort())}});
  });
  const auto hold = [&st](std::optional<StationError> (Station::*verb)()) {
    return [&st, verb](const httplib::Request& req, httplib::Response& res) {
      if (!empty_body(req.body)) return bad_request(res, req.path + " takes no body");
      if (auto e = (st.*verb)()) return refuse(res, *e);
      reply(res, 200, {{"state", to_string(st.status().state)}});
    };
  };
  server.Post("/api/pause", hold(&Station::pause));
  server.Post("/api/resume", hold(&Station::resume));
  server.Post("/api/reset", hold(&Station::reset));
  server.Put(R"(/api/vars/([^/]+))", [&st](const httplib::Request& req, httplib::Response& res) {
    const std::string name = req.matches[1];
    std::string value = req.body;
    // `echo A17 | curl -T - …` sends the line's end: one is not part of the value.
    if (!value.empty() && value.back() == '\n') value.pop_back();
    if (!value.empty() && value.back() == '\r') value.pop_back();
    for (unsigned char c : value)
      if (c < ' ' || c == 127) return bad_request(res, "PUT /api/vars/" + name + ": control characters are not allowed in a value");
    if (auto e = st.set_variable(name, value)) return refuse(res, *e);
    reply(res, 200, {{"name", name}, {"value", value}});
  });
  server.Get(R"(/api/serial/([^/]+))", [&st](const httplib::Request& req, httplib::Response& res) {
    const std::string counter = req.matches[1];
    std::optional<std::int64_t> next;
    if (auto e = st.next_serial(counter, next)) return refuse(res, *e);
    reply(res, 200, {{"counter", counter}, {"next", next ? json(*next) : json(nullptr)}});
  });
  server.Get("/api/preview", [&st](const httplib::Request&, httplib::Response& res) {
    std::vector<ObjectText> texts;
    std::map<std::string, std::int64_t> serials;
    if (auto e = st.preview(texts, serials)) return refuse(res, *e);
    reply(res, 200, preview_json(texts, serials));
  });
  // The next part's picture, drawn by the source (nothing consumed): no rendering here.
  server.Get("/api/preview.png", [&st](const httplib::Request&, httplib::Response& res) {
    std::string png;
    if (auto e = st.preview_png(png)) return refuse(res, *e);
    res.status = 200;
    res.set_header("Cache-Control", "no-store");  // a new part, a new picture
    res.set_content(std::move(png), "image/png");
  });
  server.Get("/api/log", [&st](const httplib::Request& req, httplib::Response& res) {
    AuditFilter f;
    f.limit = kLogRowsDefault;
    if (req.has_param("limit")) {
      const std::string text = req.get_param_value("limit");
      long long n = 0;
      const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
      if (text.empty() || ec != std::errc() || end != text.data() + text.size() || n < 1 || n > kLogRowsMax)
        return bad_request(res, "GET /api/log: limit=" + text.substr(0, 32) + ": the number of rows, 1 to " +
                                    std::to_string(kLogRowsMax));
      f.limit = n;
    }
    json rows = json::array();
    try {
      st.read_log(f, [&](const AuditRow& r) {
        rows.push_back(audit_to_json(r));
        return true;
      });
    } catch (const InputError& e) {
      return refuse(res, StationError{"notfound", e.what()});
    }
    reply(res, 200, rows);
  });
  server.Get("/api/events", [this](const httplib::Request&, httplib::Response& res) { stream_events(res); });
  server.Get("/", [](const httplib::Request&, httplib::Response& res) {
    res.set_content(std::string(operator_page_html()), "text/html; charset=utf-8");
  });
}

// One `data: JSON` per event from the moment the client connected, after a first comment line
// (`: station events`) that tells the client it is subscribed; a comment line every 10 s without
// an event, so a client gone is noticed. Ends (the chunked stream finished cleanly) when the
// server stops.
void HttpServer::Impl::stream_events(httplib::Response& res) {
  res.set_header("Cache-Control", "no-cache");
  std::shared_ptr<EventStream> stream = events;
  std::uint64_t seq = stream->end();
  int quiet = 0;
  ++*open_streams;
  res.set_chunked_content_provider(
      "text/event-stream", [stream, seq, quiet](std::size_t offset, httplib::DataSink& sink) mutable {
        if (offset == 0) {
          constexpr std::string_view kHello = ": station events\n\n";
          return sink.write(kHello.data(), kHello.size());
        }
        const auto data = stream->next(seq, std::chrono::milliseconds(500));
        if (!data && stream->closed()) {
          sink.done();
          return true;
        }
        if (!sink.is_writable()) return false;
        std::string chunk;
        if (data) {
          chunk = "data: " + *data + "\n\n";
          quiet = 0;
        } else if (++quiet == 20) {
          chunk = ": still here\n\n";
          quiet = 0;
        } else {
          return true;
        }
        return sink.write(chunk.data(), chunk.size());
      },
      [open = open_streams](bool) { --*open; });
}

HttpServer::HttpServer(Station& station, const ListenAddress& address, std::function<void(const std::string&)> log,
                       std::string token)
    : impl_(std::make_unique<Impl>(station, std::move(log))) {
  Impl& d = *impl_;
  d.server.new_task_queue = [] { return new httplib::ThreadPool(kHttpThreads); };
  d.server.set_payload_max_length(kHttpBodyMax);
  // cpp-httplib's default also sets SO_REUSEPORT, which lets a second station bind the same
  // port and take half the connections: SO_REUSEADDR only (a restart may rebind at once).
  d.server.set_socket_options([](int fd) {
    const int one = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  });
  d.server.set_keep_alive_timeout(2);
  d.server.set_tcp_nodelay(true);  // a reply is one response: no waiting for an ACK to send it
  // HTTP/1.1 (RFC 9112 §6.3): a request with neither Content-Length nor Transfer-Encoding has
  // an empty body. cpp-httplib 0.11 reads such a POST to the connection's end instead (`curl -X
  // POST` waits 5 s, then 400): say so before it reads.
  // The token is checked here, before the body is read and before any route runs.
  d.server.set_pre_routing_handler([token = std::move(token), log = d.log](const httplib::Request& req,
                                                                           httplib::Response& res) {
    if (!token.empty() && req.path.rfind("/api/", 0) == 0) {
      const std::optional<std::string> why = bearer_refusal(req, token);
      if (why) {
        res.set_header("WWW-Authenticate", "Bearer");
        res.set_header("Connection", "close");  // the body, if any, is not read
        reply(res, 401, {{"error", *why}});
        if (log) log("http auth: " + req.remote_addr + ": " + req.method + " " + req.path.substr(0, 128) + " refused: " + *why);
        return httplib::Server::HandlerResponse::Handled;
      }
    }
    if (!req.has_header("Content-Length") && !req.has_header("Transfer-Encoding"))
      const_cast<httplib::Request&>(req).headers.emplace("Content-Length", "0");
    return httplib::Server::HandlerResponse::Unhandled;
  });
  d.routes();
  d.server.set_error_handler([](const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty()) return;
    std::string why;
    if (res.status == 404) why = "no endpoint " + req.method + " " + req.path.substr(0, 128) + "; endpoints: " + kEndpoints;
    else if (res.status == 413) why = "the request body is over " + std::to_string(kHttpBodyMax) + " bytes";
    else if (res.status == 414) why = "the request line is too long";
    else why = "the request was refused (HTTP " + std::to_string(res.status) + ")";
    res.set_content(json_text(json{{"error", why}}), "application/json");
  });
  d.server.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) {
    std::string why = "internal error";
    try {
      std::rethrow_exception(ep);
    } catch (const std::exception& e) {
      why = e.what();
    } catch (...) {
    }
    reply(res, 500, {{"error", why}});
  });
  if (d.log)
    d.server.set_logger([log = d.log](const httplib::Request& req, const httplib::Response& res) {
      if (req.method != "GET" || res.status >= 400)
        log("http " + req.method + " " + req.path.substr(0, 128) + " " + std::to_string(res.status));
    });
  station.add_listener([stream = d.events](const StationEvent& e) { stream->publish(json_text(event_json(e))); });

  const std::string where = address.host + ":" + std::to_string(address.port);
  d.port = address.port == 0 ? d.server.bind_to_any_port(address.host)
                             : (d.server.bind_to_port(address.host, address.port) ? address.port : -1);
  if (d.port <= 0) throw InputError("--http " + where + ": cannot listen there (the port in use?)");
  d.thread = std::thread([&d] { d.server.listen_after_bind(); });
  // stop() before the thread listens would find nothing to stop and the join would hang.
  while (!d.server.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

HttpServer::~HttpServer() { stop(); }

int HttpServer::port() const { return impl_->port; }

void HttpServer::stop() {
  Impl& d = *impl_;
  d.events->close();
  // The streams send what is left and end; a client that does not read is cut off by stop().
  for (int i = 0; i < 200 && *d.open_streams > 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  d.server.stop();
  if (d.thread.joinable()) d.thread.join();
}

}  // namespace mark
