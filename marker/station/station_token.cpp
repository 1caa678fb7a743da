#include "marker/station/station_token.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "base/error.hpp"

namespace mark {

std::string read_station_token(const std::string& path, const std::string& option) {
  std::string where = option;
  where.append(" ").append(path).append(": ");
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) throw InputError(where + "cannot read the token file: " + std::strerror(errno));
  if (!S_ISREG(st.st_mode)) throw InputError(where + "the token file is not a regular file");
  if ((st.st_mode & (S_IRWXG | S_IRWXO)) != 0)
    throw InputError(where + "the token file can be read or written by group or others; chmod 600 " + path);
  std::ifstream in(path, std::ios::binary);
  std::string token;
  if (!in || !std::getline(in, token)) {
    if (!in.is_open()) throw InputError(where + "cannot read the token file: " + std::strerror(errno));
    throw InputError(where + "the token file is empty; put one line of at least " + std::to_string(kTokenMinLength) +
                     " characters in it (e.g. head -c 24 /dev/urandom | base64)");
  }
  if (!token.empty() && token.back() == '\r') token.pop_back();
  if (token.empty())
    throw InputError(where + "the token's line is empty; put one line of at least " + std::to_string(kTokenMinLength) +
                     " characters first in the file");
  for (unsigned char c : token)
    if (c <= ' ' || c == 127)
      throw InputError(where + "the token has a space or a control character; use printable characters only (e.g. base64)");
  if (token.size() < kTokenMinLength)
    throw InputError(where + "the token has " + std::to_string(token.size()) + " characters; it needs at least " +
                     std::to_string(kTokenMinLength));
  if (token.size() > kTokenCompareMax)
    throw InputError(where + "the token has " + std::to_string(token.size()) + " characters; at most " +
                     std::to_string(kTokenCompareMax));
  return token;
}

bool token_matches(std::string_view expected, std::string_view given) {
  // Every byte of a fixed window is compared, a byte past either string's end as 0, and the
  // lengths are folded in: the same steps whatever the inputs, no early exit. `volatile`
  // keeps the compiler from turning the fold into a short-circuit.
  volatile unsigned char diff = 0;
  unsigned long long length_diff = static_cast<unsigned long long>(expected.size() ^ given.size());
  for (std::size_t i = 0; i < kTokenCompareMax; ++i) {
    const unsigned char e = i < expected.size() ? static_cast<unsigned char>(expected[i]) : 0;
    const unsigned char g = i < given.size() ? static_cast<unsigned char>(given[i]) : 0;
    diff = static_cast<unsigned char>(diff | (e ^ g));
  }
  // A given token longer than the window is refused (read_station_token never accepts one).
  if (given.size() > kTokenCompareMax) length_diff |= 1;
  return diff == 0 && length_diff == 0 && !expected.empty();
}

}  // namespace mark
