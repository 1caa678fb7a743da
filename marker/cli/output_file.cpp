#include "marker/cli/output_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "fonts/error.hpp"
#include "marker/cli/interrupt.hpp"

namespace mark::cli {
namespace fs = std::filesystem;

void check_output_file(const std::string& path, std::string_view option) {
  if (path.empty()) return;
  const auto refuse = [&](const std::string& why) {
    return InputError(std::string(option) + " " + path + ": cannot write there: " + why);
  };
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw refuse("it is a folder");
  const fs::path dir = fs::path(path).has_parent_path() ? fs::path(path).parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec)) throw refuse(std::strerror(ENOENT));
  // The file is written under a temporary name in the same folder and renamed: the folder must
  // be writable, whether or not the file exists.
  if (::access(dir.c_str(), W_OK | X_OK) != 0) throw refuse(std::strerror(errno));
}

void write_file_whole(const std::string& path,
                      const std::function<void(const std::string&)>& write) {
  const fs::path target(path);
  // Same folder (so the rename is atomic), same extension (writers pick the format by it).
  const std::string tmp =
      (target.has_parent_path() ? target.parent_path() / "" : fs::path()).string() + "." +
      target.stem().string() + ".tmp-" + std::to_string(::getpid()) + target.extension().string();
  try {
    write(tmp);
    // Ctrl-C while writing: the file is not finished, so it does not replace anything.
    if (interrupt_flag().requested()) throw Interrupted();
  } catch (...) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw;
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw InputError("cannot write " + path + ": " + ec.message());
  }
}

}  // namespace mark::cli
