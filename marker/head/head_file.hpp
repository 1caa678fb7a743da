#pragma once
// The head's small JSON files — head profiles, lag patterns — read and checked one way: whole,
// at most 1 MiB (anything larger is not one), one object of the stated format and version,
// every number within its range. Every error is one line, "KIND WHERE: what", KIND naming the
// file's kind ("head profile") and WHERE the file.
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

namespace mark {

struct HeadFileKind {
  std::string_view name;    // "head profile": begins every message
  std::string_view format;  // the "format" value
  int version = 1;
};

[[noreturn]] void head_file_error(const HeadFileKind& kind, std::string_view where, const std::string& what);

// The file's bytes; throws InputError when it cannot be read or is larger than 1 MiB.
std::string read_head_file(const HeadFileKind& kind, const std::string& path);

// The text as one object with the kind's "format" and "version"; throws InputError otherwise.
nlohmann::json parse_head_file(const HeadFileKind& kind, std::string_view text, std::string_view where);

// j[key] as a number within lo .. hi; `fallback` when absent and not required. Throws
// InputError "'KEY' is missing", "'KEY' must be a number", "'KEY' is V, outside LO to HI".
double head_file_number(const HeadFileKind& kind, const nlohmann::json& j, const char* key, double lo,
                        double hi, std::string_view where, bool required = true, double fallback = 0);

}  // namespace mark
