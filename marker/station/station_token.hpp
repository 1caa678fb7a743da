#pragma once
// The station's shared secret (`marker serve --token FILE`, docs/station.md "Token"): with it,
// every TCP session and every HTTP API request authenticates before anything runs, and the
// station may listen beyond loopback. Read once at start; compared in constant time.
#include <string>
#include <string_view>

namespace mark {

// The shortest token accepted: 16 characters (`head -c 24 /dev/urandom | base64` gives 32).
inline constexpr std::size_t kTokenMinLength = 16;

// The token in `path`: its first line, the line's end (LF, CRLF) stripped. Throws InputError
// naming `option` and the file when it is missing or unreadable, empty, shorter than
// kTokenMinLength, holds spaces or control characters, or can be read or written by group or
// others (a secret others can read is no secret: "chmod 600 FILE", as ssh asks of its keys).
std::string read_station_token(const std::string& path, const std::string& option);

// Whether `given` is `expected`, in time that depends on neither where they first differ nor
// on `given`'s length: every byte of a fixed kTokenCompareMax window is compared (past a
// string's end as 0) and the lengths folded in, so the loop always runs the same steps. A
// `given` longer than the window never matches (read_station_token refuses such a token).
inline constexpr std::size_t kTokenCompareMax = 256;
bool token_matches(std::string_view expected, std::string_view given);

}  // namespace mark
