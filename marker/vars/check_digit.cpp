#include "marker/vars/check_digit.hpp"

#include <array>

#include "base/error.hpp"

namespace mark {
namespace {

struct Named {
  CheckDigit algorithm;
  std::string_view name;
};
constexpr std::array<Named, 6> kNames{{{CheckDigit::luhn, "luhn"},
                                       {CheckDigit::mod10, "mod10"},
                                       {CheckDigit::mod11, "mod11"},
                                       {CheckDigit::iso7064_11_2, "iso7064-11-2"},
                                       {CheckDigit::iso7064_37_36, "iso7064-37-36"},
                                       {CheckDigit::vin, "vin"}}};

[[noreturn]] void refuse(CheckDigit a, std::string_view text, std::size_t at, const char* wanted) {
  throw InputError("{check:" + std::string(to_string(a)) + "}: '" + std::string(1, text[at]) + "' at character " +
                   std::to_string(at + 1) + " of \"" + std::string(text) + "\" is not " + wanted);
}

// The characters the check covers (separators skipped), each one the algorithm takes.
std::string covered_characters(CheckDigit a, std::string_view text, bool alphanumeric) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == ' ' || c == '-') continue;
    const bool digit = c >= '0' && c <= '9', upper = c >= 'A' && c <= 'Z';
    if (!digit && !(alphanumeric && upper)) refuse(a, text, i, alphanumeric ? "a digit or a capital A–Z" : "a digit");
    out += c;
  }
  if (out.empty())
    throw InputError("{check:" + std::string(to_string(a)) + "}: there is nothing before it to check");
  return out;
}

char digit(int v) { return static_cast<char>('0' + v); }

char luhn(const std::string& d) {
  int sum = 0;
  bool twice = true;  // the rightmost digit of the payload is doubled (the check will follow it)
  for (auto it = d.rbegin(); it != d.rend(); ++it, twice = !twice) {
    int v = *it - '0';
    if (twice) v = v * 2 > 9 ? v * 2 - 9 : v * 2;
    sum += v;
  }
  return digit((10 - sum % 10) % 10);
}

char gs1_mod10(const std::string& d) {
  int sum = 0, w = 3;
  for (auto it = d.rbegin(); it != d.rend(); ++it, w = 4 - w) sum += w * (*it - '0');
  return digit((10 - sum % 10) % 10);
}

char mod11(const std::string& d) {
  long long sum = 0, w = 2;
  for (auto it = d.rbegin(); it != d.rend(); ++it, ++w) sum += w * (*it - '0');
  const int c = static_cast<int>((11 - sum % 11) % 11);
  return c == 10 ? 'X' : digit(c);
}

char iso7064_11_2(const std::string& d) {
  int p = 0;
  for (char c : d) p = ((p + (c - '0')) * 2) % 11;
  const int c = (12 - p) % 11;
  return c == 10 ? 'X' : digit(c);
}

int alnum_value(char c) { return c <= '9' ? c - '0' : c - 'A' + 10; }

char iso7064_37_36(const std::string& d) {
  // Hybrid system, M = 36, M + 1 = 37 (ISO 7064 §7).
  int p = 36;
  for (char c : d) {
    int s = (p % 37 + alnum_value(c)) % 36;
    if (s == 0) s = 36;
    p = (s * 2) % 37;
  }
  const int c = (37 - p) % 36;
  return c < 10 ? digit(c) : static_cast<char>('A' + c - 10);
}

// 49 CFR 565.15: letters transliterated, weights by position, the sum mod 11.
char vin(std::string_view before, std::string_view after) {
  const std::string text = std::string(before) + "?" + std::string(after);
  if (before.size() != 8 || after.size() != 8)
    throw InputError("{check:vin}: a VIN is 17 characters with the check at the 9th; the text is \"" + text +
                     "\" (" + std::to_string(before.size()) + " before the check, " + std::to_string(after.size()) +
                     " after)");
  static constexpr int kWeights[17] = {8, 7, 6, 5, 4, 3, 2, 10, 0, 9, 8, 7, 6, 5, 4, 3, 2};
  static constexpr std::string_view kLetters = "ABCDEFGHJKLMNPRSTUVWXYZ";
  static constexpr int kValues[] = {1, 2, 3, 4, 5, 6, 7, 8, 1, 2, 3, 4, 5, 7, 9, 2, 3, 4, 5, 6, 7, 8, 9};
  int sum = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (i == 8) continue;
    const char c = text[i];
    int v;
    if (c >= '0' && c <= '9') {
      v = c - '0';
    } else if (const std::size_t k = kLetters.find(c); k != std::string_view::npos) {
      v = kValues[k];
    } else {
      refuse(CheckDigit::vin, text, i, "a VIN character (0–9, A–Z but I, O and Q)");
    }
    sum += v * kWeights[i];
  }
  const int c = sum % 11;
  return c == 10 ? 'X' : digit(c);
}

}  // namespace

std::optional<CheckDigit> parse_check_digit(std::string_view name) {
  for (const Named& n : kNames)
    if (n.name == name) return n.algorithm;
  return std::nullopt;
}

std::string_view to_string(CheckDigit c) {
  for (const Named& n : kNames)
    if (n.algorithm == c) return n.name;
  return "?";
}

std::string check_digit_names() {
  std::string s;
  for (const Named& n : kNames) s += (s.empty() ? "" : ", ") + std::string(n.name);
  return s;
}

char check_character(CheckDigit a, std::string_view covered, std::string_view after) {
  switch (a) {
    case CheckDigit::luhn: return luhn(covered_characters(a, covered, false));
    case CheckDigit::mod10: return gs1_mod10(covered_characters(a, covered, false));
    case CheckDigit::mod11: return mod11(covered_characters(a, covered, false));
    case CheckDigit::iso7064_11_2: return iso7064_11_2(covered_characters(a, covered, false));
    case CheckDigit::iso7064_37_36: return iso7064_37_36(covered_characters(a, covered, true));
    case CheckDigit::vin: return vin(covered, after);
  }
  return '?';
}

}  // namespace mark
