#include "marker/vars/alphabet.hpp"

#include <algorithm>

#include "base/error.hpp"
#include "fonts/utf8.hpp"

namespace mark {
namespace {

std::vector<std::string> ascii_symbols(std::string_view digits) {
  std::vector<std::string> s;
  for (char c : digits) s.emplace_back(1, c);
  return s;
}

}  // namespace

std::string_view to_string(Padding p) {
  switch (p) {
    case Padding::keep: return "keep";
    case Padding::suppress: return "suppress";
    case Padding::blank: return "blank";
  }
  return "?";
}

std::optional<Padding> parse_padding(std::string_view name) {
  for (Padding p : {Padding::keep, Padding::suppress, Padding::blank})
    if (name == to_string(p)) return p;
  return std::nullopt;
}

Alphabet::Alphabet() : name_("decimal"), symbols_(ascii_symbols("0123456789")) {}

std::optional<Alphabet> Alphabet::named(std::string_view name) {
  Alphabet a;
  if (name == "decimal") return a;
  a.name_ = std::string(name);
  if (name == "hex") {
    a.symbols_ = ascii_symbols("0123456789ABCDEF");
  } else if (name == "base36") {
    a.symbols_ = ascii_symbols("0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ");
  } else if (name == "base33") {
    a.symbols_ = ascii_symbols("0123456789ABCDEFGHJKLMNPRSTUVWXYZ");
  } else {
    return std::nullopt;
  }
  return a;
}

Alphabet Alphabet::custom(std::string_view utf8_digits, std::string_view what) {
  const std::u32string cps = decode_utf8(utf8_digits, what);
  Alphabet a;
  a.custom_ = true;
  a.name_ = std::string(utf8_digits);
  a.symbols_.clear();
  for (std::size_t i = 0; i < cps.size(); ++i) {
    const char32_t c = cps[i];
    if (c == U' ' || c == U'{' || c == U'}' || c == U'\n' || c < 0x20)
      throw InputError(std::string(what) + ": a space, a brace or a control character cannot be a digit");
    if (cps.find(c) != i)
      throw InputError(std::string(what) + ": '" + encode_utf8(c) + "' appears twice");
    a.symbols_.push_back(encode_utf8(c));
  }
  if (a.symbols_.size() < 2)
    throw InputError(std::string(what) + ": an alphabet needs at least 2 distinct characters");
  return a;
}

int Alphabet::digits(std::int64_t value) const {
  std::uint64_t v = static_cast<std::uint64_t>(value < 0 ? 0 : value);
  int n = 1;
  while (v >= base()) v /= base(), ++n;
  return n;
}

std::int64_t Alphabet::max_for_width(int width) const {
  if (width <= 0) return INT64_MAX;
  unsigned __int128 m = 1;
  for (int i = 0; i < width; ++i) {
    m *= base();
    if (m > static_cast<unsigned __int128>(INT64_MAX)) return INT64_MAX;
  }
  return static_cast<std::int64_t>(m - 1);
}

void Alphabet::format(std::int64_t value, int width, Padding padding, std::string& out) const {
  // Digits least significant first into a small stack buffer (64 base-2 digits at most).
  std::size_t idx[64];
  int n = 0;
  std::uint64_t v = static_cast<std::uint64_t>(value < 0 ? 0 : value);
  do {
    idx[n++] = static_cast<std::size_t>(v % base());
    v /= base();
  } while (v > 0);
  for (int i = n; i < width; ++i) {
    if (padding == Padding::keep) out += symbols_[0];
    if (padding == Padding::blank) out += ' ';
  }
  while (n > 0) out += symbols_[idx[--n]];
}

}  // namespace mark
