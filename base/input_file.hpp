#pragma once
// A file the user named, read whole and bounded: a job file, a head profile, a correction file,
// a data list. A directory, a file that cannot be opened, or one longer than the kind allows is
// refused in one line naming the path; a pipe or a device (/dev/zero) is read no further than
// the bound, so nothing the user names can exhaust memory.
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "base/error.hpp"

namespace mark {

// "16 MiB", "512 KiB" or "100 bytes": a bound as a refusal states it.
inline std::string byte_count_text(std::size_t bytes) {
  if (bytes >= (1u << 20) && bytes % (1u << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  if (bytes >= (1u << 10) && bytes % (1u << 10) == 0) return std::to_string(bytes >> 10) + " KiB";
  return std::to_string(bytes) + " bytes";
}

// The bytes of `path`, a `what` ("job file"), at most `max_bytes`. Throws InputError
// "PATH: cannot read the WHAT: WHY".
inline std::string read_input_file(const std::string& path, std::string_view what, std::size_t max_bytes) {
  const auto fail = [&](const std::string& why) {
    throw InputError(path + ": cannot read the " + std::string(what) + ": " + why);
  };
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) fail("it is a directory");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(errno ? std::strerror(errno) : "cannot open it");
  std::string text;
  char block[1 << 16];
  while (in) {
    in.read(block, sizeof block);
    text.append(block, static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_bytes)
      fail("longer than " + byte_count_text(max_bytes) + ", the most a " + std::string(what) + " may be");
  }
  if (in.bad()) fail("a read error");
  return text;
}

}  // namespace mark
