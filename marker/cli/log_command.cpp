// `marker log (--job FILE | --store PATH|URL) [--since T] [--json | --csv]`: the audit log, one
// row per mark (and re-mark, reservation, counter set): time (UTC), station, job and its
// SHA-256, texts, serial values, outcome and the device's figures.
#include <iostream>

#include "base/error.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/production_options.hpp"
#include "marker/limits/production_settings.hpp"
#include "marker/store/audit_format.hpp"
#include "marker/store/open_store.hpp"
#include "marker/store/utc_time.hpp"

namespace mark::cli {

Command make_log_command() {
  struct Args {
    std::string job, store, since;
    bool json = false, csv = false;
  };
  auto a = std::make_shared<Args>();
  return Command(
      [a](CLI::App& app) {
        auto* sub = app.add_subcommand("log", "print the audit log of a serial store");
        sub->add_option("--job", a->job, "job file (its store is next to it)");
        sub->add_option("--store", a->store, "serial store: SQLite file or postgresql://…");
        add_setting(*sub, kSince, a->since);
        auto* json = sub->add_flag("--json", a->json, "JSON Lines: one object per row");
        auto* csv = sub->add_flag("--csv", a->csv, "CSV with a header row");
        json->excludes(csv);
        return sub;
      },
      [a] {
        std::string since;
        if (!a->since.empty()) {
          const auto t = parse_since(a->since, SystemClock().now());
          if (!t)
            throw InputError("--since '" + a->since + "': expected a UTC date or time (2026-03-05, "
                             "2026-03-05T06:00) or a span back from now (90m, 12h, 7d)");
          since = format_utc(*t);
        }
        auto store = open_store(store_location(a->store, a->job), StoreAccess::existing);
        const std::vector<AuditRow> rows = store->log(since);
        if (a->csv) std::cout << audit_csv_header() << "\n";
        for (const AuditRow& r : rows) {
          if (a->json)
            std::cout << audit_to_json(r).dump() << "\n";
          else if (a->csv)
            std::cout << audit_to_csv(r) << "\n";
          else
            std::cout << audit_to_line(r) << "\n";
        }
        return 0;
      });
}

}  // namespace mark::cli
