#pragma once
// Strict reading of one JSON object of a job file: every key a reader asks for is marked used,
// finish() refuses the rest (a typo must not silently mark with defaults, so it names the key
// and the closest known one), and every error names the file, the JSON path and the problem:
// "job.json: objects[2].pen: no pen named \"deep\"".
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "marker/limits/setting.hpp"
#include "marker/limits/value_range.hpp"

namespace mark {

class JsonReader {
 public:
  // `j` must outlive the reader. Throws if `j` is not an object.
  JsonReader(const nlohmann::json& j, std::string file, std::string path);

  const std::string& path() const { return path_; }
  const std::string& file() const { return file_; }
  std::string path_of(std::string_view key) const;
  bool has(std::string_view key);
  const nlohmann::json* raw(std::string_view key);  // marks it used; nullptr if absent

  std::optional<std::string> string(std::string_view key);

  // A setting's key (marker/limits/: the same range, choices and words as its command-line
  // option); a key with dots ("circle.cx_mm") is read by its last part in the object it names.
  std::optional<double> number(const Quantity& s);
  // Within `range`: the setting's, narrowed by what is known now (the head's positioning limit).
  std::optional<double> number(const Quantity& s, const Range& range);
  // The value, or the setting's default.
  double number_or_default(const Quantity& s) { return number(s).value_or(s.fallback()); }
  std::optional<std::int64_t> integer(const Count& s);
  std::optional<std::string> choice(const Choice& s);
  std::optional<bool> boolean(const Toggle& s);
  std::optional<std::string> string(const Text& s);
  // Finite number within the range (marker/limits/: the same ranges as the command line's).
  std::optional<double> number(std::string_view key, const Range& range);
  // Finite number within [lo, hi] (named with `unit` in the error).
  std::optional<double> number(std::string_view key, double lo, double hi, std::string_view unit = "");
  // Whole number within the range (64-bit; 1.0 is not accepted for a whole number).
  std::optional<std::int64_t> integer(std::string_view key, const WholeRange& range);
  std::optional<std::int64_t> integer(std::string_view key, std::int64_t lo, std::int64_t hi);
  std::optional<bool> boolean(std::string_view key);
  // One of `choices`.
  std::optional<std::string> choice(std::string_view key, const std::vector<std::string>& choices);
  JsonReader object(std::string_view key);  // required to be an object when present

  // Throws for the first key nobody asked for.
  void finish() const;

  // While set, every key any reader asks for (present or not) is appended as its JSON path
  // ("pens.fine.speed_mm_s"): the settings test takes this census of a whole job to find keys
  // that no settings table declares. Null (no census) otherwise; not for concurrent parses.
  inline static std::vector<std::string>* census = nullptr;
  [[noreturn]] void fail(std::string_view key, const std::string& problem) const;
  [[noreturn]] void fail_here(const std::string& problem) const;

 private:
  const nlohmann::json* find(std::string_view key);
  const nlohmann::json& j_;
  std::string file_;
  std::string path_;
  std::set<std::string, std::less<>> used_;
};

// "objects[2]" / "pens.deep" style path joins.
std::string json_path(std::string_view parent, std::string_view key);
std::string json_index(std::string_view parent, std::size_t index);
// The closest of `known` to `key` by edit distance (nothing when none is close).
std::optional<std::string> closest_key(std::string_view key, const std::vector<std::string>& known);

}  // namespace mark
