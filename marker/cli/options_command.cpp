// `marker options [TABLE] [--markdown | --json]`: the settings tables (marker/limits/), each
// setting with its command-line option, its job-file key, its range, its default and its
// meaning. `--markdown TABLE` prints the table the docs hold between
// `<!-- settings: TABLE -->` and `<!-- end settings -->` (scripts/docs_tables.sh copies it there;
// a test fails when the docs differ).
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "marker/cli/commands.hpp"
#include "marker/limits/setting_tables.hpp"

namespace mark::cli {
namespace {

struct OptionsArgs {
  std::string table;
  bool markdown = false;
  bool json = false;
};

std::string kind_of(const SettingRef& s) {
  static constexpr const char* kKinds[] = {"number", "whole number", "choice", "on/off", "text"};
  return kKinds[s.index()];
}

nlohmann::json setting_json(const SettingRef& s) {
  const SettingName& n = name_of(s);
  nlohmann::json j = {{"option", n.flag}, {"key", n.key},           {"kind", kind_of(s)},
                      {"range", range_text(s)}, {"default", default_text(s)}, {"meaning", n.help}};
  if (const auto* q = std::get_if<const Quantity*>(&s)) {
    j["min"] = (*q)->bounds.min;
    j["max"] = (*q)->bounds.max;
    j["unit"] = (*q)->bounds.unit;
  }
  return j;
}

std::vector<const SettingTable*> chosen(const std::string& id) {
  if (id.empty()) return {std::begin(kSettingTables), std::end(kSettingTables)};
  if (const SettingTable* t = find_setting_table(id)) return {t};
  std::string ids;
  for (const SettingTable* t : kSettingTables) ids += (ids.empty() ? "" : ", ") + std::string(t->id);
  throw InputError("options: '" + id + "' is not a settings table (" + ids + ")");
}

int run_options(const OptionsArgs& a) {
  const std::vector<const SettingTable*> tables = chosen(a.table);
  if (a.json) {
    nlohmann::json out = nlohmann::json::array();
    for (const SettingTable* t : tables) {
      nlohmann::json settings = nlohmann::json::array();
      for (const SettingRef& s : t->settings) settings.push_back(setting_json(s));
      out.push_back({{"table", t->id}, {"title", t->title}, {"place", t->place}, {"settings", settings}});
    }
    std::cout << nlohmann::json{{"tables", out}}.dump(2) << "\n";
    return 0;
  }
  for (const SettingTable* t : tables) {
    if (a.markdown) {
      std::cout << markdown_table(*t);
      continue;
    }
    std::printf("%s settings (%s)%s%s\n", std::string(t->title).c_str(), std::string(t->id).c_str(),
                t->place.empty() ? "" : ", job-file keys in ", std::string(t->place).c_str());
    for (const SettingRef& s : t->settings) {
      const SettingName& n = name_of(s);
      std::printf("  %-30s %-26s %s; %s (default %s)\n", n.flag.empty() ? "-" : std::string(n.flag).c_str(),
                  n.key.empty() ? "-" : std::string(n.key).c_str(), std::string(n.help).c_str(),
                  range_text(s).c_str(), default_text(s).c_str());
    }
  }
  return 0;
}

}  // namespace

Command make_options_command() {
  auto a = std::make_shared<OptionsArgs>();
  return Command(
      [a](CLI::App& app) {
        auto* sub = app.add_subcommand(
            "options", "list every setting: its option, its job-file key, its range, its default and its meaning");
        sub->add_option("table", a->table, "one table (head, pen, layout, …; default: all)");
        auto* md = sub->add_flag("--markdown", a->markdown, "print Markdown tables, as the docs hold them");
        auto* json = sub->add_flag("--json", a->json, "print one JSON object (docs/json.md)");
        md->excludes(json);
        return sub;
      },
      [a] { return run_options(*a); });
}

}  // namespace mark::cli
