#include "marker/production/json_reader.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "base/error.hpp"

namespace mark {
namespace {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

// The last part of a setting's key: its name in the object the reader reads.
std::string_view leaf(const SettingName& n) {
  const std::size_t dot = n.key.rfind('.');
  return dot == std::string_view::npos ? n.key : n.key.substr(dot + 1);
}

const char* type_name(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null: return "null";
    case nlohmann::json::value_t::boolean: return "true/false";
    case nlohmann::json::value_t::string: return "a string";
    case nlohmann::json::value_t::array: return "a list";
    case nlohmann::json::value_t::object: return "an object";
    default: return "a number";
  }
}

}  // namespace

std::string json_path(std::string_view parent, std::string_view key) {
  return parent.empty() ? std::string(key) : std::string(parent) + "." + std::string(key);
}

std::string json_index(std::string_view parent, std::size_t index) {
  return std::string(parent) + "[" + std::to_string(index) + "]";
}

std::optional<std::string> closest_key(std::string_view key, const std::vector<std::string>& known) {
  std::optional<std::string> best;
  std::size_t best_d = std::max<std::size_t>(2, key.size() / 3) + 1;
  for (const std::string& k : known) {
    const std::size_t d = edit_distance(key, k);
    if (d < best_d) best_d = d, best = k;
  }
  return best;
}

JsonReader::JsonReader(const nlohmann::json& j, std::string file, std::string path)
    : j_(j), file_(std::move(file)), path_(std::move(path)) {
  if (!j_.is_object())
    throw InputError(file_ + ": " + (path_.empty() ? std::string("the job") : path_) +
                     ": expected an object {…}, found " + type_name(j_));
}

std::string JsonReader::path_of(std::string_view key) const { return json_path(path_, key); }

void JsonReader::fail(std::string_view key, const std::string& problem) const {
  throw InputError(file_ + ": " + path_of(key) + ": " + problem);
}

void JsonReader::fail_here(const std::string& problem) const {
  throw InputError(file_ + ": " + (path_.empty() ? std::string("the job") : path_) + ": " + problem);
}

const nlohmann::json* JsonReader::find(std::string_view key) {
  used_.insert(std::string(key));  // asked for: a known key, present or not
  if (census) census->push_back(path_of(key));
  const auto it = j_.find(std::string(key));
  return it == j_.end() ? nullptr : &*it;
}

bool JsonReader::has(std::string_view key) { return find(key) != nullptr; }

const nlohmann::json* JsonReader::raw(std::string_view key) { return find(key); }

std::optional<std::string> JsonReader::string(std::string_view key) {
  const nlohmann::json* v = find(key);
  if (!v) return std::nullopt;
  if (!v->is_string()) fail(key, std::string("expected a string, found ") + type_name(*v));
  return v->get<std::string>();
}

std::optional<double> JsonReader::number(std::string_view key, double lo, double hi,
                                         std::string_view unit) {
  return number(key, Range{lo, hi, std::string(unit)});
}

std::optional<double> JsonReader::number(std::string_view key, const Range& range) {
  const nlohmann::json* v = find(key);
  if (!v) return std::nullopt;
  if (!v->is_number()) fail(key, std::string("expected a number, found ") + type_name(*v));
  const double d = v->get<double>();
  // The command line's words for the same refusal (value_range.hpp's check_range).
  if (!range.contains(d)) fail(key, format_number(d) + " is outside the range " + range.text());
  return d;
}

std::optional<double> JsonReader::number(const Quantity& s) { return number(leaf(s.name), s.range()); }

std::optional<double> JsonReader::number(const Quantity& s, const Range& range) {
  return number(leaf(s.name), range);
}

std::optional<std::int64_t> JsonReader::integer(const Count& s) { return integer(leaf(s.name), s.range); }

std::optional<std::string> JsonReader::choice(const Choice& s) { return choice(leaf(s.name), s.names()); }

std::optional<bool> JsonReader::boolean(const Toggle& s) { return boolean(leaf(s.name)); }

std::optional<std::string> JsonReader::string(const Text& s) { return string(leaf(s.name)); }

std::optional<std::int64_t> JsonReader::integer(std::string_view key, std::int64_t lo,
                                                std::int64_t hi) {
  return integer(key, WholeRange{lo, hi});
}

std::optional<std::int64_t> JsonReader::integer(std::string_view key, const WholeRange& range) {
  const nlohmann::json* v = find(key);
  if (!v) return std::nullopt;
  std::int64_t i = 0;
  if (v->is_number_unsigned()) {
    const auto u = v->get<std::uint64_t>();
    if (u > static_cast<std::uint64_t>(INT64_MAX))
      fail(key, std::to_string(u) + " does not fit in 64 bits (at most " + std::to_string(INT64_MAX) + ")");
    i = static_cast<std::int64_t>(u);
  } else if (v->is_number_integer()) {
    i = v->get<std::int64_t>();
  } else {
    fail(key, std::string("expected a whole number, found ") +
                  (v->is_number() ? "a fraction" : type_name(*v)));
  }
  if (!range.contains(i)) fail(key, std::to_string(i) + " is outside the range " + range.text());
  return i;
}

std::optional<bool> JsonReader::boolean(std::string_view key) {
  const nlohmann::json* v = find(key);
  if (!v) return std::nullopt;
  if (!v->is_boolean()) fail(key, std::string("expected true or false, found ") + type_name(*v));
  return v->get<bool>();
}

std::optional<std::string> JsonReader::choice(std::string_view key,
                                              const std::vector<std::string>& choices) {
  const std::optional<std::string> s = string(key);
  if (!s) return s;
  if (std::find(choices.begin(), choices.end(), *s) == choices.end()) {
    std::string list;
    for (const std::string& c : choices) list += (list.empty() ? "" : ", ") + c;
    fail(key, "\"" + *s + "\" is not one of " + list);
  }
  return s;
}

JsonReader JsonReader::object(std::string_view key) {
  const nlohmann::json* v = find(key);
  static const nlohmann::json empty = nlohmann::json::object();
  if (!v) return JsonReader(empty, file_, path_of(key));
  if (!v->is_object()) fail(key, std::string("expected an object {…}, found ") + type_name(*v));
  return JsonReader(*v, file_, path_of(key));
}

void JsonReader::finish() const {
  std::vector<std::string> known(used_.begin(), used_.end());
  for (const auto& [k, v] : j_.items()) {
    if (used_.count(k)) continue;
    (void)v;
    const auto near = closest_key(k, known);
    fail(k, near ? "unknown key (did you mean \"" + *near + "\"?)" : "unknown key");
  }
}

}  // namespace mark
