#include "marker/station/line_auth.hpp"

#include <cctype>

#include "marker/station/station_token.hpp"

namespace mark {

LineAuth::Verdict LineAuth::check(std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  const std::size_t sp = line.find(' ');
  std::string verb(line.substr(0, sp));
  for (char& c : verb) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (verb != "AUTH") {
    if (authenticated()) return {};
    return {true, "ERR auth give AUTH <token> first; nothing else runs before it", false,
            "refused a command before AUTH"};
  }
  if (token_.empty()) return {true, "OK auth (no token set)", false, {}};
  const std::string_view given = sp == std::string_view::npos ? std::string_view{} : line.substr(sp + 1);
  if (token_matches(token_, given)) {
    authenticated_ = true;
    wrong_ = 0;
    return {true, "OK auth", false, {}};
  }
  // A wrong AUTH after a right one ends the session's authentication too: whoever types it
  // does not hold the token now.
  authenticated_ = false;
  ++wrong_;
  const bool close = wrong_ >= kAuthTriesMax;
  std::string reply = "ERR auth wrong token";
  std::string log = "wrong token (" + std::to_string(wrong_) + " of " + std::to_string(kAuthTriesMax) + ")";
  if (close) {
    reply += "; closing after " + std::to_string(kAuthTriesMax) + " wrong tries";
    log += ", connection closed";
  }
  return {true, std::move(reply), close, std::move(log)};
}

}  // namespace mark
