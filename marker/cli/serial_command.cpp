// `marker serial create NAME [--start N] [--job FILE] [--store …] [--station S]`
// `marker serial show NAME [--job FILE] [--store PATH|URL] [--json]`
// `marker serial set NAME VALUE --job FILE [--store …] [--station S]`
// `marker serial reserve NAME COUNT --job FILE [--store …] [--station S] [--json]`
// Create, inspect and administer the counters of the station's store (or --store). A counter
// exists only once created, so a renamed counter or a typo in a template is refused instead of
// starting at 1. The job gives a counter's rules (start, step, limit, resets); setting a
// counter at or behind an already-issued value is refused; every creation, set and reservation
// is an audit row. `show` only reads (a read-only transaction; it works on a read-only file).
#include <iostream>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/interrupt.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/production_options.hpp"
#include "marker/limits/production_settings.hpp"
#include "marker/production/job_file.hpp"
#include "marker/store/open_store.hpp"

namespace mark::cli {
namespace {

struct SerialArgs {
  std::string name;
  long long value = 0;
  long long count = 0;
  std::optional<long long> start;
  std::string job, station;
  StoreArgs store;
  bool json = false;
};

struct Loaded {
  std::optional<JobFile> job;
  std::string bytes;
  const CounterSpec* spec = nullptr;
};

Loaded load(const SerialArgs& a, bool need_job) {
  Loaded l;
  if (a.job.empty()) {
    if (need_job) throw InputError("serial: give --job FILE: the job holds the counter's rules (step, limit, resets)");
    return l;
  }
  l.job = read_job_file(a.job, &l.bytes);
  const auto it = l.job->counters.find(a.name);
  if (it == l.job->counters.end()) throw InputError(a.job + ": no counter named \"" + a.name + "\"");
  l.spec = &it->second;
  return l;
}

StoreSettings settings() {
  StoreSettings s;
  s.interrupts = interrupt_count;
  return s;
}

int show(const SerialArgs& a) {
  Loaded l = load(a, false);
  const SysTime now = SystemClock().now();
  const ShiftTable shifts = l.job ? l.job->shifts : ShiftTable{};
  // Read-only: showing never creates a store, takes no write lock and works on a file this
  // process cannot write.
  auto store = open_production_store(a.store, StoreAccess::read_only, settings());
  const CounterStatus st = store->status(a.name, l.spec, shifts, now);
  if (!st.known)
    throw InputError("the store " + store->describe() + " has no counter \"" + a.name +
                     "\": create it with `marker serial create " + a.name + " [--start N]`");
  auto opt = [](const std::optional<std::int64_t>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); };
  if (a.json) {
    std::cout << nlohmann::json{{"name", a.name}, {"next", opt(st.next)},
                                {"highest_issued", opt(st.highest_issued)},
                                {"lowest_issued", opt(st.lowest_issued)},
                                {"period", st.state.period}, {"cycle", st.state.cycle},
                                {"store", store->describe()}}
                     .dump()
              << "\n";
    return 0;
  }
  std::string next = st.next ? std::to_string(*st.next) : "none (the counter has passed its limit)";
  if (st.next && l.spec) next += " (\"" + l.spec->alphabet.format(*st.next, l.spec->width, l.spec->padding) + "\")";
  std::printf("counter %s in %s\n  next %s\n  highest issued %s\n", a.name.c_str(), store->describe().c_str(),
              next.c_str(), st.highest_issued ? std::to_string(*st.highest_issued).c_str() : "none");
  if (!st.state.period.empty()) std::printf("  period %s\n", st.state.period.c_str());
  if (st.state.cycle) std::printf("  cycle %lld (wrapped)\n", static_cast<long long>(st.state.cycle));
  return 0;
}

int create(const SerialArgs& a) {
  Loaded l = load(a, false);
  std::int64_t start = 1;
  if (a.start) start = *a.start;
  else if (l.spec) start = l.spec->start;
  if (l.spec && l.spec->beyond(start))
    throw InputError("serial create " + a.name + " --start " + std::to_string(start) +
                     ": outside the counter's range in " + a.job + " (limit " +
                     std::to_string(l.spec->effective_limit()) + ")");
  auto store = open_production_store(a.store, StoreAccess::create, settings());
  MarkContext ctx = mark_context(a.station, a.job, l.bytes);
  ctx.now = SystemClock().now();
  // With the job, the counter starts in the current reset period: the first part counts from
  // `start`, not from the job's start of a "new" period.
  const std::string period = l.spec ? period_key(*l.spec, ctx.now, l.job->shifts) : "";
  store->create_counter(a.name, start, period, ctx);
  std::printf("counter %s created: next value %lld\n", a.name.c_str(), static_cast<long long>(start));
  return 0;
}

int set_or_reserve(const SerialArgs& a, bool reserve) {
  Loaded l = load(a, true);
  auto store = open_production_store(a.store, StoreAccess::existing, settings());
  MarkContext ctx = mark_context(a.station, a.job, l.bytes);
  ctx.now = SystemClock().now();
  if (!reserve) {
    store->set(*l.spec, a.value, l.job->shifts, ctx);
    std::printf("counter %s: next value %lld\n", a.name.c_str(), a.value);
    return 0;
  }
  const std::vector<Issue> issued = store->reserve(*l.spec, a.count, l.job->shifts, ctx);
  if (a.json) {
    nlohmann::json values = nlohmann::json::array();
    for (const Issue& i : issued) values.push_back(i.value);
    std::cout << nlohmann::json{{"name", a.name}, {"reserved", values}}.dump() << "\n";
  } else {
    std::printf("counter %s: reserved %zu value(s), %lld to %lld\n", a.name.c_str(), issued.size(),
                static_cast<long long>(issued.front().value), static_cast<long long>(issued.back().value));
  }
  return 0;
}

}  // namespace

Command make_serial_command() {
  auto a = std::make_shared<SerialArgs>();
  auto subs = std::make_shared<std::array<CLI::App*, 4>>();
  return Command(
      [=](CLI::App& app) {
        auto* serial = app.add_subcommand("serial", "create, inspect and administer serial counters");
        serial->require_subcommand(1);
        auto common = [&](CLI::App* s) {
          s->add_option("name", a->name, "counter name")->required();
          s->add_option("--job", a->job, "job file (the counter's rules)");
          add_store_options(*s, a->store, false);
        };
        auto* create = serial->add_subcommand("create", "create a counter in the store (a job's counters must be created before it marks)");
        common(create);
        add_setting(*create, kCreateStart, a->start);
        add_setting(*create, kStation, a->station);
        auto* show = serial->add_subcommand("show", "the counter's next value and highest issued value (read-only)");
        common(show);
        show->add_flag("--json", a->json, "print one JSON object (next, highest_issued)");
        auto* set = serial->add_subcommand("set", "make VALUE the counter's next value (never at or behind an issued one)");
        common(set);
        add_setting(*set, kSerialValue, a->value)->required();
        add_setting(*set, kStation, a->station);
        auto* reserve = serial->add_subcommand("reserve", "issue COUNT values without marking");
        common(reserve);
        add_setting(*reserve, kReserveCount, a->count)->required();
        add_setting(*reserve, kStation, a->station);
        reserve->add_flag("--json", a->json, "print the reserved values as JSON");
        *subs = {create, show, set, reserve};
        return serial;
      },
      [=] {
        if ((*subs)[0]->parsed()) return create(*a);
        if ((*subs)[1]->parsed()) return show(*a);
        return set_or_reserve(*a, (*subs)[3]->parsed());
      });
}

}  // namespace mark::cli
