#pragma once
// One TCP session's authentication (docs/station.md, "Token"): with a token set, the first
// command must be `AUTH <token>`; until it is, every other line gets `ERR auth ...` and is not
// run (STATUS too: a session that has not authenticated learns nothing and changes nothing).
// kAuthTriesMax wrong tokens end the session. Without a token, `AUTH anything` answers
// `OK auth (no token set)`, so one client script works with both stations.
#include <string>
#include <string_view>

namespace mark {

// Wrong AUTH lines a session may send before the station closes it.
inline constexpr int kAuthTriesMax = 3;

class LineAuth {
 public:
  explicit LineAuth(std::string token) : token_(std::move(token)) {}

  struct Verdict {
    bool handled = false;     // the line was AUTH, or refused: `reply` answers it, it is not run
    std::string reply;        // when handled
    bool close = false;       // the session ends after the reply (too many wrong tokens)
    std::string log;          // a refusal to log (never the token); empty: nothing to log
  };
  // Looks at one command line (without its newline): AUTH, or any line before a right AUTH, is
  // answered here; other lines pass (handled false) to station_command.
  Verdict check(std::string_view line);
  bool authenticated() const { return token_.empty() || authenticated_; }

 private:
  std::string token_;  // empty: no token set
  bool authenticated_ = false;
  int wrong_ = 0;
};

}  // namespace mark
