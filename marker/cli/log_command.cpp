// `marker log [--store PATH|URL] [--limit N] [--since T] [--serial [COUNTER=]VALUE] [--text T]
//  [--job FILE] [--json | --csv]`: the audit log of the station's store (or --store), one row
// per mark (and re-mark, reservation, counter creation or set): time (UTC), station, job and its
// SHA-256, texts, serial values with their period and cycle, outcome and the device's figures.
// Reading never blocks a station: a read-only transaction on a snapshot, rows streamed to the
// output one at a time (constant memory whatever the size of the log), on a read-only file too.
#include <charconv>
#include <iostream>

#include "base/error.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/interrupt.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/production_options.hpp"
#include "marker/limits/production_settings.hpp"
#include "marker/store/audit_format.hpp"
#include "marker/store/open_store.hpp"
#include "marker/store/utc_time.hpp"

namespace mark::cli {
namespace {

struct LogArgs {
  StoreArgs store;
  std::string since, serial, job;
  std::optional<std::string> text;
  std::optional<long long> limit;
  bool json = false, csv = false;
};

// "41" or "serial=41".
void parse_serial(const std::string& s, AuditFilter& f) {
  const std::size_t eq = s.find('=');
  const std::string number = eq == std::string::npos ? s : s.substr(eq + 1);
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), v);
  if (number.empty() || ec != std::errc() || end != number.data() + number.size() || v < 0 ||
      (eq != std::string::npos && eq == 0))
    throw InputError("--serial '" + s + "': expected a value (41) or COUNTER=VALUE (serial=41), the value 0 to " +
                     std::to_string(INT64_MAX));
  f.value = v;
  if (eq != std::string::npos) f.counter = s.substr(0, eq);
}

int run_log(const LogArgs& a) {
  AuditFilter f;
  if (!a.since.empty()) {
    const auto t = parse_since(a.since, SystemClock().now());
    if (!t)
      throw InputError("--since '" + a.since + "': expected a UTC date or time (2026-03-05, "
                       "2026-03-05T06:00) or a span back from now (90m, 12h, 7d)");
    f.since_utc = format_utc(*t);
  }
  if (!a.serial.empty()) parse_serial(a.serial, f);
  f.text = a.text;
  f.limit = a.limit;
  f.job = a.job;
  StoreSettings settings;
  settings.interrupts = interrupt_count;
  auto store = open_production_store(a.store, StoreAccess::read_only, std::move(settings));
  if (a.csv) std::cout << audit_csv_header() << "\n";
  store->read_log(f, [&](const AuditRow& r) {
    if (a.json)
      std::cout << audit_to_json(r).dump() << "\n";
    else if (a.csv)
      std::cout << audit_to_csv(r) << "\n";
    else
      std::cout << audit_to_line(r) << "\n";
    // A reader gone (`marker log | head`) or Ctrl-C ends the read, not the station.
    return std::cout.good() && !interrupt_flag().requested();
  });
  std::cout.flush();
  return interrupt_flag().requested() ? kExitInterrupted : 0;
}

}  // namespace

Command make_log_command() {
  auto a = std::make_shared<LogArgs>();
  return Command(
      [a](CLI::App& app) {
        auto* sub = app.add_subcommand("log", "print the audit log of the serial store (read-only)");
        add_store_options(*sub, a->store, false);
        add_setting(*sub, kLogLimit, a->limit);
        add_setting(*sub, kSince, a->since);
        add_setting(*sub, kLogSerial, a->serial);
        add_setting(*sub, kLogText, a->text);
        sub->add_option("--job", a->job, "rows marked with this job file (its path as the mark was given it)");
        auto* json = sub->add_flag("--json", a->json, "JSON Lines: one object per row");
        auto* csv = sub->add_flag("--csv", a->csv, "CSV with a header row");
        json->excludes(csv);
        return sub;
      },
      [a] { return run_log(*a); });
}

}  // namespace mark::cli
