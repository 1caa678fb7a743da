#include "marker/limits/setting.hpp"

#include <algorithm>
#include <stdexcept>
#include <type_traits>

namespace mark {
namespace {

std::string quoted_list(std::string_view choices) {
  std::string out;
  std::size_t start = 0;
  while (start <= choices.size()) {
    const std::size_t end = std::min(choices.find(", ", start), choices.size());
    out += (out.empty() ? "`" : ", `") + std::string(choices.substr(start, end - start)) + "`";
    start = end + 2;
  }
  return out;
}

}  // namespace

double Quantity::fallback() const {
  if (!value) throw std::logic_error(std::string(name.flag.empty() ? name.key : name.flag) + " has no default");
  return *value;
}

std::int64_t Count::fallback() const {
  if (!value) throw std::logic_error(std::string(name.flag.empty() ? name.key : name.flag) + " has no default");
  return *value;
}

std::vector<std::string> Choice::names() const {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= choices.size()) {
    const std::size_t end = std::min(choices.find(", ", start), choices.size());
    out.emplace_back(choices.substr(start, end - start));
    start = end + 2;
  }
  return out;
}

bool Choice::allows(std::string_view v) const {
  for (const std::string& n : names())
    if (n == v) return true;
  return false;
}

const SettingName& name_of(const SettingRef& s) {
  return std::visit([](const auto* p) -> const SettingName& { return p->name; }, s);
}

std::string range_text(const SettingRef& s) {
  return std::visit(
      [](const auto* p) -> std::string {
        using T = std::remove_cvref_t<decltype(*p)>;
        if constexpr (std::is_same_v<T, Quantity>) return p->range().text();
        else if constexpr (std::is_same_v<T, Count>) return p->range.text();
        else if constexpr (std::is_same_v<T, Choice>) return quoted_list(p->choices);
        else if constexpr (std::is_same_v<T, Toggle>) return "on or off";
        else return "text";
      },
      s);
}

std::string default_text(const SettingRef& s) {
  return std::visit(
      [](const auto* p) -> std::string {
        using T = std::remove_cvref_t<decltype(*p)>;
        std::optional<std::string> given;
        if constexpr (std::is_same_v<T, Toggle>) {
          return p->on ? "on" : "off";
        } else {
          if constexpr (std::is_same_v<T, Quantity>) {
            if (p->value) given = format_number(*p->value);
          } else if constexpr (std::is_same_v<T, Count>) {
            if (p->value) given = std::to_string(*p->value);
          } else {
            // Appended, not `"`" + … + "`"`: GCC 12 warns a false -Wrestrict on that sum.
            if (!p->value.empty()) given = std::string("`").append(p->value).append("`");
          }
          if (!p->derived.empty()) return std::string(p->derived);
          return given ? *given : std::string("—");
        }
      },
      s);
}

void check_setting(const Quantity& s, double v) {
  check_range(s.name.flag.empty() ? s.name.key : s.name.flag, v, s.range());
}

Range limited_range(const Quantity& s, double max, std::string_view why) {
  Range r = s.range();
  r.max = std::min(r.max, max);
  if (!why.empty()) r.unit += " (" + std::string(why) + ")";
  return r;
}

}  // namespace mark
