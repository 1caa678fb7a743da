// `marker store path`: where this station's serial store and outcome journals are.
// `marker store check [--store PATH|URL] [--quick] [--json]`: the store's own check (SQLite:
// PRAGMA integrity_check and the foreign keys; --quick: PRAGMA quick_check, what every
// station start runs) and the store's rules (every counter's next value lies past what it
// issued); read-only, exit 1 when anything is wrong.
// `marker store backup FILE [--store PATH]`: a checked copy of an SQLite store taken while
// stations mark (SQLite's online backup API), written whole or not at all.
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/interrupt.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/production_options.hpp"
#include "marker/limits/production_settings.hpp"
#include "marker/output/output_file.hpp"
#include "marker/store/open_store.hpp"
#include "marker/store/sqlite_backup.hpp"

namespace mark::cli {
namespace {

struct StoreCommandArgs {
  StoreArgs store;
  std::string target;
  bool quick = false, json = false;
};

int path() {
  std::printf("store %s\njournal %s\n(folder from %s)\n", default_store_path().c_str(),
              default_journal_dir().c_str(),
              std::getenv("STATE_DIRECTORY") && std::getenv("STATE_DIRECTORY")[0] == '/' ? "$STATE_DIRECTORY (a service)"
              : std::getenv("XDG_STATE_HOME") && std::getenv("XDG_STATE_HOME")[0] == '/' ? "$XDG_STATE_HOME"
              : std::getenv("HOME") && std::getenv("HOME")[0] == '/'                      ? "$HOME/.local/state"
                                                                                           : "no home: /var/lib/marker");
  return 0;
}

int check(const StoreCommandArgs& a) {
  StoreSettings settings;
  settings.interrupts = interrupt_count;
  auto store = open_production_store(a.store, StoreAccess::read_only, std::move(settings));
  const std::vector<std::string> problems = store->check(a.quick);
  if (a.json) {
    std::cout << nlohmann::json{{"store", store->describe()}, {"quick", a.quick}, {"ok", problems.empty()},
                                {"problems", problems}}
                     .dump()
              << "\n";
  } else if (problems.empty()) {
    std::printf("%s: ok (%s)\n", store->describe().c_str(), a.quick ? "quick_check" : "integrity_check, foreign keys, counters");
  } else {
    for (const std::string& p : problems) std::printf("%s: %s\n", store->describe().c_str(), p.c_str());
  }
  return problems.empty() ? 0 : 1;
}

int backup(const StoreCommandArgs& a) {
  const std::string source = store_location(a.store.store);
  if (is_postgres_url(source))
    throw InputError("store backup copies an SQLite store; back up a PostgreSQL store with pg_dump");
  check_output_path("store backup FILE", a.target);
  std::error_code ec;
  if (std::filesystem::exists(a.target) && std::filesystem::equivalent(source, a.target, ec))
    throw InputError("store backup '" + a.target + "': that is the store itself");
  std::cerr << "marker: store sqlite:" << source << "\n";
  const BackupReport r = backup_sqlite_store(source, a.target);
  std::printf("backup of sqlite:%s written to %s: %lld bytes, %lld audit rows, quick_check ok\n", source.c_str(),
              r.target.c_str(), static_cast<long long>(r.bytes), static_cast<long long>(r.rows));
  return 0;
}

}  // namespace

Command make_store_command() {
  auto a = std::make_shared<StoreCommandArgs>();
  auto subs = std::make_shared<std::array<CLI::App*, 3>>();
  return Command(
      [=](CLI::App& app) {
        auto* store = app.add_subcommand("store", "the serial store itself: where it is, check it, back it up");
        store->require_subcommand(1);
        auto* p = store->add_subcommand("path", "where this station's store and outcome journals are");
        auto* c = store->add_subcommand("check", "check the store (read-only; exit 1 when damaged)");
        add_store_options(*c, a->store, false);
        add_setting(*c, kQuickCheck, a->quick);
        c->add_flag("--json", a->json, "one JSON object: store, ok, problems");
        auto* b = store->add_subcommand("backup", "copy an SQLite store while stations mark (online backup)");
        b->add_option("file", a->target, "the copy to write (written whole or not at all)")->required();
        add_store_options(*b, a->store, false);
        *subs = {p, c, b};
        return store;
      },
      [=] {
        if ((*subs)[0]->parsed()) return path();
        if ((*subs)[1]->parsed()) return check(*a);
        return backup(*a);
      });
}

}  // namespace mark::cli
