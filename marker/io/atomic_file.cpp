#include "marker/io/atomic_file.hpp"

#include <filesystem>
#include <fstream>

#include "fonts/error.hpp"

namespace mark {

void write_file_atomically(const std::string& path, const std::string& text) {
  const std::string temp = path + ".part";
  std::error_code ec;
  {
    std::ofstream out(temp, std::ios::binary);
    if (!out) throw InputError("output file '" + path + "': cannot be written");
    out << text;
    out.close();
    if (!out) {
      std::filesystem::remove(temp, ec);
      throw InputError("output file '" + path + "': write failed");
    }
  }
  std::filesystem::rename(temp, path, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw InputError("output file '" + path + "': " + ec.message());
  }
}

}  // namespace mark
