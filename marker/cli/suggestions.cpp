#include "marker/cli/suggestions.hpp"

#include <algorithm>

namespace mark::cli {
namespace {

// Optimal string alignment distance (Levenshtein with adjacent transpositions).
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// The subcommand being parsed when the error came: the deepest one the command line selected.
const CLI::App* deepest_parsed(const CLI::App& app) {
  const CLI::App* at = &app;
  while (!at->get_subcommands().empty()) at = at->get_subcommands().front();
  return at;
}

std::string command_path(const CLI::App* app) {
  std::string path;
  for (const CLI::App* at = app; at && at->get_parent(); at = at->get_parent())
    path = at->get_name() + (path.empty() ? "" : " " + path);
  return path;
}

std::vector<std::string> option_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* o : app.get_options()) {
    for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
    for (const std::string& s : o->get_snames()) names.push_back("-" + s);
  }
  return names;
}

std::vector<std::string> subcommand_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* s : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(s->get_name());
  return names;
}

std::string did_you_mean(const std::optional<std::string>& name) {
  return name ? " (did you mean " + *name + "?)" : "";
}

}  // namespace

std::optional<std::string> closest_name(std::string_view typed, const std::vector<std::string>& known) {
  // "-x" is one edit from every short option: too short to guess what was meant.
  if (typed.size() < 4) return std::nullopt;
  const std::size_t allowed = typed.size() <= 4 ? 1 : typed.size() <= 8 ? 2 : 3;
  std::optional<std::string> best;
  std::size_t best_distance = allowed + 1;
  for (const std::string& k : known) {
    const std::size_t d = edit_distance(typed, k);
    if (d < best_distance) best = k, best_distance = d;
  }
  return best;
}

std::string parse_error_line(const CLI::App& app, const CLI::ParseError& error) {
  const CLI::App* at = deepest_parsed(app);
  const std::string where = command_path(at);
  // An argument the command does not take: the first that looks like an option, else the first.
  if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
    const std::vector<std::string> left = at->remaining();
    const auto option = std::find_if(left.begin(), left.end(), [](const std::string& a) { return a.starts_with("-"); });
    if (option != left.end()) {
      const std::string typed = option->substr(0, option->find('='));
      return where + ": unknown option " + typed + did_you_mean(closest_name(typed, option_names(*at)));
    }
    if (!left.empty() && !subcommand_names(*at).empty())
      return where + ": '" + left.front() + "' is not a command of " + where +
             did_you_mean(closest_name(left.front(), subcommand_names(*at)));
  }
  // No (known) command: the first word is a mistyped one, or there is none.
  if (dynamic_cast<const CLI::RequiredError*>(&error) && at->get_subcommands().empty() &&
      !subcommand_names(*at).empty()) {
    const std::vector<std::string> left = at->remaining();
    if (left.empty())
      return (where.empty() ? "" : where + ": ") + "give a command; `marker " + (where.empty() ? "" : where + " ") +
             "--help` lists them";
    if (!left.empty() && !left.front().starts_with("-"))
      return (where.empty() ? "" : where + ": ") + "'" + left.front() + "' is not a command" +
             did_you_mean(closest_name(left.front(), subcommand_names(*at))) + "; `marker " +
             (where.empty() ? "" : where + " ") + "--help` lists them";
  }
  return error.what();
}

}  // namespace mark::cli
