// Fuzz target for the station's HTTP interface (marker/station/http_server.hpp): the input is
// sent as it is, as raw bytes of one or more requests, to an HttpServer on loopback (started
// once) over a station with a part source that marks at once. The first answer must be an
// HTTP/1.1 status line, or nothing (the server closed a connection it could not parse); every
// 4xx and 5xx answer's body is a JSON object with a string "error". The event stream is left
// out (an answer without end: the tests cover it). Anything else, or a sanitizer report, is a bug.

#include <cctype>
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "fuzz_check.hpp"
#include "fuzz_loopback.hpp"
#include "fuzz_station_source.hpp"
#include "marker/station/http_server.hpp"

using mark::fuzz::broken;

namespace {

struct Served {
  mark::fuzz::NullSource source;
  mark::Station station{source};
  mark::HttpServer http{station, mark::parse_listen_address("127.0.0.1:0", "--http")};
};

Served& served() {
  static Served* s = new Served;  // lives for the process: libFuzzer exits without destructors
  return *s;
}

// The input with %XX decoded, lower-cased: does it ask for the event stream in any spelling?
bool asks_for_events(const std::string& in) {
  std::string d;
  for (std::size_t i = 0; i < in.size(); ++i) {
    if (in[i] == '%' && i + 2 < in.size() && std::isxdigit(static_cast<unsigned char>(in[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(in[i + 2]))) {
      d += static_cast<char>(std::stoi(in.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      d += in[i];
    }
  }
  for (char& c : d) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return d.find("event") != std::string::npos;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string request(reinterpret_cast<const char*>(data), size);
  if (asks_for_events(request)) return -1;  // not kept in the corpus
  Served& s = served();
  const std::string reply = mark::fuzz::exchange_on_loopback(s.http.port(), request.data(), request.size());
  s.station.wait_idle();
  s.station.resume();  // a PAUSE does not hold the next input back
  if (reply.empty()) return 0;
  if (reply.rfind("HTTP/1.1 ", 0) != 0 || reply.size() < 12) broken("an answer that is not an HTTP/1.1 status line");
  const int status = std::stoi(reply.substr(9, 3));
  if (status < 400) return 0;
  const std::size_t head_end = reply.find("\r\n\r\n");
  if (head_end == std::string::npos) broken("an answer without the end of its header");
  std::string head = reply.substr(0, head_end);
  for (char& c : head) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::size_t cl = head.find("\r\ncontent-length: ");
  if (cl == std::string::npos) broken("an error answer without Content-Length");
  const std::size_t length = std::stoul(head.substr(cl + 18));
  // A server that answers and closes with request bytes still unread resets the connection
  // (TCP RST), which may cut the answer short on the client's side: judge only a whole one.
  if (reply.size() < head_end + 4 + length) return 0;
  const nlohmann::json body = nlohmann::json::parse(reply.substr(head_end + 4, length), nullptr, false);
  if (!body.is_object() || !body.contains("error") || !body["error"].is_string()) broken("an error answer without {\"error\": …}");
  return 0;
}
