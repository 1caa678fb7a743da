#include "marker/head/head_file.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "base/error.hpp"
#include "base/input_file.hpp"

namespace mark {
namespace {

std::string fmt(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

void head_file_error(const HeadFileKind& kind, std::string_view where, const std::string& what) {
  throw InputError(std::string(kind.name) + " " + std::string(where) + ": " + what);
}

std::string read_head_file(const HeadFileKind& kind, const std::string& path) {
  return read_input_file(path, kind.name, 1u << 20);
}

nlohmann::json parse_head_file(const HeadFileKind& kind, std::string_view text, std::string_view where) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // syntax, or a number out of range (1e400)
    head_file_error(kind, where, std::string("not JSON (") + e.what() + ")");
  }
  if (!j.is_object()) head_file_error(kind, where, "must be one JSON object");
  const auto format = j.find("format");
  if (format == j.end() || !format->is_string() || format->get<std::string>() != kind.format)
    head_file_error(kind, where, "'format' must be \"" + std::string(kind.format) + "\"");
  const auto version = j.find("version");
  if (version == j.end() || !version->is_number_integer() || version->get<long long>() != kind.version)
    head_file_error(kind, where, "'version' must be " + std::to_string(kind.version));
  return j;
}

double head_file_number(const HeadFileKind& kind, const nlohmann::json& j, const char* key, double lo,
                        double hi, std::string_view where, bool required, double fallback) {
  const auto it = j.find(key);
  if (it == j.end()) {
    if (required) head_file_error(kind, where, std::string("'") + key + "' is missing");
    return fallback;
  }
  if (!it->is_number()) head_file_error(kind, where, std::string("'") + key + "' must be a number");
  const double v = it->get<double>();
  if (!std::isfinite(v) || v < lo || v > hi)
    head_file_error(kind, where, std::string("'") + key + "' is " + fmt(v) + ", outside " + fmt(lo) + " to " + fmt(hi));
  return v;
}

}  // namespace mark
