// `marker serial show NAME (--job FILE | --store PATH|URL) [--json]`
// `marker serial set NAME VALUE --job FILE [--store …] [--station S]`
// `marker serial reserve NAME COUNT --job FILE [--store …] [--station S] [--json]`
// Inspect and administer counters. The job gives the counter's rules (step, limit, resets);
// setting a counter at or behind an already-issued value is refused; every set and reservation
// is an audit row.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "base/error.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/production_options.hpp"
#include "marker/limits/production_settings.hpp"
#include "marker/production/job_file.hpp"
#include "marker/store/open_store.hpp"

namespace mark::cli {
namespace {

struct Args {
  std::string name;
  long long value = 0;
  long long count = 0;
  std::string job, store, station;
  bool json = false;
};

struct Loaded {
  std::optional<JobFile> job;
  std::string bytes;
  const CounterSpec* spec = nullptr;
};

Loaded load(const Args& a, bool need_job) {
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

int show(const Args& a) {
  Loaded l = load(a, false);
  const std::string where = store_location(a.store, a.job);
  const SysTime now = SystemClock().now();
  const ShiftTable shifts = l.job ? l.job->shifts : ShiftTable{};
  CounterStatus st;
  // Showing never creates a store: a job without one yet shows its counter's start.
  if (!is_postgres_url(where) && !std::filesystem::exists(where)) {
    if (!l.spec) throw StoreError("serial store " + where + " does not exist");
    st.name = a.name;
    st.state = CounterState::fresh(*l.spec, period_key(*l.spec, now, shifts));
    if (auto p = peek(*l.spec, st.state, st.state.period)) st.next = p->value;
  } else {
    st = open_store(where, StoreAccess::existing)->status(a.name, l.spec, shifts, now);
    if (!st.known && !l.spec) throw InputError("the store " + where + " has no counter \"" + a.name + "\"");
  }
  auto opt = [](const std::optional<std::int64_t>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); };
  if (a.json) {
    std::cout << nlohmann::json{{"name", a.name}, {"next", opt(st.next)},
                                {"highest_issued", opt(st.highest_issued)},
                                {"lowest_issued", opt(st.lowest_issued)},
                                {"period", st.state.period}, {"cycle", st.state.cycle},
                                {"store", where}}
                     .dump()
              << "\n";
    return 0;
  }
  std::string next = st.next ? std::to_string(*st.next) : "none (the counter has passed its limit)";
  if (st.next && l.spec) next += " (\"" + l.spec->alphabet.format(*st.next, l.spec->width, l.spec->padding) + "\")";
  std::printf("counter %s in %s\n  next %s\n  highest issued %s\n", a.name.c_str(), where.c_str(),
              next.c_str(), st.highest_issued ? std::to_string(*st.highest_issued).c_str() : "none");
  if (!st.state.period.empty()) std::printf("  period %s\n", st.state.period.c_str());
  if (st.state.cycle) std::printf("  cycle %lld (wrapped)\n", static_cast<long long>(st.state.cycle));
  return 0;
}

int set_or_reserve(const Args& a, bool reserve) {
  Loaded l = load(a, true);
  auto store = open_store(store_location(a.store, a.job), StoreAccess::create);
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
  auto a = std::make_shared<Args>();
  auto subs = std::make_shared<std::array<CLI::App*, 3>>();
  return Command(
      [=](CLI::App& app) {
        auto* serial = app.add_subcommand("serial", "inspect and administer serial counters");
        serial->require_subcommand(1);
        auto common = [&](CLI::App* s) {
          s->add_option("name", a->name, "counter name")->required();
          s->add_option("--job", a->job, "job file (the counter's rules; its store is next to it)");
          s->add_option("--store", a->store, "serial store: SQLite file or postgresql://…");
        };
        auto* show = serial->add_subcommand("show", "the counter's next value and highest issued value");
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
        *subs = {show, set, reserve};
        return serial;
      },
      [=] {
        if ((*subs)[0]->parsed()) return show(*a);
        return set_or_reserve(*a, (*subs)[2]->parsed());
      });
}

}  // namespace mark::cli
