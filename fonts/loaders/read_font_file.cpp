#include "fonts/loaders/read_font_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "fonts/error.hpp"

namespace fs = std::filesystem;

namespace mark::loaders {

namespace {
constexpr std::uintmax_t kMaxFontFileBytes = 64u << 20;
}  // namespace

std::string read_font_file(const std::string& path) {
  const auto fail = [&](const std::string& why) {
    throw InputError("cannot read font file '" + path + "': " + why);
  };
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) fail(ec ? ec.message() : "no such file");
  if (fs::is_directory(status)) fail("it is a directory");
  if (!fs::is_regular_file(status)) fail("not a regular file");
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) fail(ec.message());
  if (size > kMaxFontFileBytes) fail("larger than 64 MiB, not a font");

  std::ifstream in(path, std::ios::binary);
  if (!in) fail(std::strerror(errno));
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(size));
  if (in.gcount() != static_cast<std::streamsize>(size)) fail("read error");
  return text;
}

}  // namespace mark::loaders
