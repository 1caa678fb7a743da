#include "marker/cli/option_ranges.hpp"

#include <cmath>
#include <type_traits>
#include <variant>

#include "base/error.hpp"
#include "marker/cli/option_values.hpp"

namespace mark::cli {
namespace {

constexpr std::string_view kRangeTag = " (range: ";

// `bounded` false: a number is all that is checked now (its range is checked once the head is known).
CLI::Validator range_validator(const Range& range, bool bounded = true) {
  CLI::Validator v(
      [range, bounded](std::string& value) -> std::string {
        const std::optional<double> n = parse_number(value);
        if (!n) return "'" + value + "' is not a number (range: " + range.text() + ")";
        if (bounded && (!std::isfinite(*n) || !range.contains(*n)))
          return value + " is outside the range " + range.text();
        return {};
      },
      "", "range");
  return v;
}

CLI::Validator whole_validator(const WholeRange& range) {
  return CLI::Validator(
      [range](std::string& value) -> std::string {
        const std::optional<long long> n = parse_whole_number(value);
        if (!n) return "'" + value + "' is not a whole number (range: " + range.text() + ")";
        if (!range.contains(*n)) return value + " is outside the range " + range.text();
        return {};
      },
      "", "range");
}

// Help texts are plain: the docs' backticks are left out.
std::string plain(std::string_view text) {
  std::string out;
  for (char c : text)
    if (c != '`') out += c;
  return out;
}

// "… (default: 5)", unless there is none or it goes without saying (a toggle is off).
std::string with_default(std::string text, const SettingRef& s) {
  const std::string d = default_text(s);
  if (d != "—" && !std::holds_alternative<const Toggle*>(s)) text += " (default: " + plain(d) + ")";
  return text;
}

CLI::Validator choice_validator(const Choice& s) {
  return CLI::Validator(
      [&s](std::string& value) -> std::string {
        if (s.allows(value)) return {};
        return "'" + value + "' is not one of " + std::string(s.choices);
      },
      "", "choice");
}

template <class T, class S>
CLI::Option* add_numeric_setting(CLI::App& app, const S& s, T& value, std::string_view prefix,
                                 bool bounded = true) {
  // A plain value starts at the default; an optional one stays unset ("not given" means the
  // default in words, which depends on other settings).
  constexpr bool plain_value = std::is_arithmetic_v<T>;
  if constexpr (plain_value)
    if (s.value) value = static_cast<T>(*s.value);
  CLI::Option* o = app.add_option(flag_of(s.name, prefix), value, setting_description(&s));
  if constexpr (std::is_same_v<S, Quantity>)
    o->check(range_validator(s.range(), bounded));
  else
    o->check(whole_validator(s.range));
  if constexpr (std::is_same_v<T, std::vector<double>>) o->delimiter(',');
  return o;
}

}  // namespace

std::string flag_of(const SettingName& n, std::string_view prefix) {
  const std::string flag(n.flag);
  if (prefix.empty()) return flag;
  return "--" + std::string(prefix) + flag.substr(2);
}

std::string setting_description(const SettingRef& setting) {
  const std::string help = with_default(plain(name_of(setting).help), setting);
  return std::visit(
      [&](const auto* s) -> std::string {
        using T = std::remove_cvref_t<decltype(*s)>;
        if constexpr (std::is_same_v<T, Quantity>)
          return help + std::string(kRangeTag) + s->range().text() + ")";
        else if constexpr (std::is_same_v<T, Count>)
          return help + std::string(kRangeTag) + s->range.text() + ")";
        else if constexpr (std::is_same_v<T, Choice>)
          return help + " (one of: " + std::string(s->choices) + ")";
        else
          return help;
      },
      setting);
}

CLI::Option* add_setting(CLI::App& app, const Quantity& s, double& value, std::string_view prefix) {
  return add_numeric_setting(app, s, value, prefix);
}
CLI::Option* add_setting(CLI::App& app, const Quantity& s, std::optional<double>& value, std::string_view prefix) {
  return add_numeric_setting(app, s, value, prefix);
}
CLI::Option* add_setting(CLI::App& app, const Quantity& s, std::vector<double>& values, std::string_view prefix) {
  return add_numeric_setting(app, s, values, prefix);
}
CLI::Option* add_head_limited_setting(CLI::App& app, const Quantity& s, double& value) {
  return add_numeric_setting(app, s, value, {}, false);
}
CLI::Option* add_head_limited_setting(CLI::App& app, const Quantity& s, std::optional<double>& value) {
  return add_numeric_setting(app, s, value, {}, false);
}
CLI::Option* add_setting(CLI::App& app, const Count& s, int& value, std::string_view prefix) {
  return add_numeric_setting(app, s, value, prefix);
}
CLI::Option* add_setting(CLI::App& app, const Count& s, long long& value, std::string_view prefix) {
  return add_numeric_setting(app, s, value, prefix);
}
CLI::Option* add_setting(CLI::App& app, const Count& s, std::optional<long long>& value, std::string_view prefix) {
  return add_numeric_setting(app, s, value, prefix);
}

CLI::Option* add_setting(CLI::App& app, const Choice& s, std::string& value, std::string_view prefix) {
  if (!s.value.empty()) value = s.value;
  return app.add_option(flag_of(s.name, prefix), value, setting_description(&s))->check(choice_validator(s));
}

CLI::Option* add_setting(CLI::App& app, const Toggle& s, bool& value, std::string_view prefix) {
  value = s.on;
  std::string flag = flag_of(s.name, prefix);
  if (s.on) flag += ",!--no-" + flag.substr(2);  // on unless turned off
  return app.add_flag(flag, value, setting_description(&s));
}

CLI::Option* add_setting(CLI::App& app, const Text& s, std::string& value, std::string_view prefix) {
  if (!s.value.empty()) value = s.value;
  return app.add_option(flag_of(s.name, prefix), value, setting_description(&s));
}

CLI::Option* add_setting(CLI::App& app, const Text& s, std::optional<std::string>& value) {
  return app.add_option(std::string(s.name.flag), value, setting_description(&s));
}

CLI::Option* add_setting(CLI::App& app, const Text& s, std::vector<std::string>& values) {
  return app.add_option(std::string(s.name.flag), values, setting_description(&s));
}

CLI::Option* add_setting(CLI::App& app, const Quantity& s, std::string& value, std::string_view word,
                         std::string_view word_help) {
  value = word;
  const std::string description = plain(s.name.help) + "; or " + std::string(word) + ": " + plain(word_help) +
                                  " (default: " + std::string(word) + ")" + std::string(kRangeTag) +
                                  s.range().text() + ")";
  // Nothing is checked while parsing: the number's range depends on the head, and a word that is
  // not `word` is refused with that range too (number_or_word, once the head is known).
  return app.add_option(std::string(s.name.flag), value, description);
}

std::optional<double> number_or_word(const Quantity& s, const std::string& value, std::string_view word,
                                     const Range& range) {
  if (value == word) return std::nullopt;
  const std::optional<double> v = parse_number(value);
  if (!v)
    throw InputError(std::string(s.name.flag) + ": '" + value + "' is neither " + std::string(word) +
                     " nor a number (range: " + range.text() + ")");
  check_range(s.name.flag, *v, range, value);
  return v;
}

std::optional<std::string> registered_range(const CLI::Option& option) {
  const std::string& d = option.get_description();
  const std::size_t at = d.rfind(kRangeTag);
  if (at == std::string::npos || d.back() != ')') return std::nullopt;
  const std::size_t from = at + kRangeTag.size();
  return d.substr(from, d.size() - 1 - from);
}

}  // namespace mark::cli
