#include "marker/limits/setting_tables.hpp"

namespace mark {
namespace {

// Cells hold no pipes: a "|" inside a cell would split it.
std::string cell(std::string_view text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string code_cell(std::string_view text) {
  if (text.empty()) return "";
  // "--self-centred,--self-centered" → `--self-centred`, `--self-centered`
  std::string out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    out += (out.empty() ? "`" : ", `") + std::string(text.substr(start, end - start)) + "`";
    start = end + 1;
  }
  return out;
}

}  // namespace

const SettingTable* find_setting_table(std::string_view id) {
  for (const SettingTable* t : kSettingTables)
    if (t->id == id) return t;
  return nullptr;
}

std::string markdown_table(const SettingTable& table) {
  std::string out = "| option | job key | range | default | meaning |\n|---|---|---|---|---|\n";
  for (const SettingRef& s : table.settings) {
    const SettingName& n = name_of(s);
    out += "| " + code_cell(n.flag) + " | " + code_cell(n.key) + " | " + cell(range_text(s)) + " | " +
           cell(default_text(s)) + " | " + cell(n.help) + " |\n";
  }
  return out;
}

}  // namespace mark
