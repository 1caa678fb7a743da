#include "marker/codes/gs1_text.hpp"

#include <algorithm>

#include "base/error.hpp"

namespace mark {
namespace {

[[noreturn]] void bad(std::string_view text, std::size_t at, const std::string& what) {
  throw InputError("GS1 data '" + std::string(text) + "', character " + std::to_string(at + 1) +
                   ": " + what);
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

std::vector<Gs1Field> parse_gs1_text(std::string_view text) {
  if (text.empty()) throw InputError("GS1 data is empty; write it as (01)09506000134352(10)LOT42");
  const char open = text.front();
  if (open != '(' && open != '[') bad(text, 0, "expected '(' or '[' before the first AI");
  const char close = open == '(' ? ')' : ']';
  std::vector<Gs1Field> fields;
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] != open) bad(text, i, std::string("expected '") + open + "' starting an AI");
    const std::size_t end = text.find(close, i + 1);
    if (end == std::string_view::npos) bad(text, i, std::string("no '") + close + "' after the AI");
    Gs1Field f;
    f.ai = std::string(text.substr(i + 1, end - i - 1));
    if (f.ai.size() < 2 || f.ai.size() > 4 || !std::all_of(f.ai.begin(), f.ai.end(), is_digit))
      bad(text, i + 1, "AI '" + f.ai + "' is not 2 to 4 digits");
    i = end + 1;
    const std::size_t next = text.find(open, i);
    const std::size_t data_end = next == std::string_view::npos ? text.size() : next;
    f.data = std::string(text.substr(i, data_end - i));
    if (f.data.empty()) bad(text, i, "AI (" + f.ai + ") has no data");
    if (f.data.find(close) != std::string::npos) bad(text, i, std::string("stray '") + close + "'");
    fields.push_back(std::move(f));
    i = data_end;
  }
  return fields;
}

bool gs1_length_predefined(std::string_view ai) {
  if (ai.size() < 2) return false;
  const int two = (ai[0] - '0') * 10 + (ai[1] - '0');
  return (two >= 0 && two <= 4) || (two >= 11 && two <= 20) || (two >= 31 && two <= 36) || two == 41;
}

std::string gs1_element_string(const std::vector<Gs1Field>& fields) {
  std::string out;
  for (std::size_t k = 0; k < fields.size(); ++k) {
    out += fields[k].ai + fields[k].data;
    if (k + 1 < fields.size() && !gs1_length_predefined(fields[k].ai)) out += '\x1d';
  }
  return out;
}

}  // namespace mark
