// SerialStore: creating, inspecting, setting and reserving counters, and reading the log.
#include "marker/limits/production_settings.hpp"
#include "marker/store/serial_store.hpp"
#include "marker/store/utc_time.hpp"

namespace mark {
namespace {

// An audit row of the counters' administration (created, set, a value reserved): who, when,
// which job; appended with its outcome in the caller's transaction.
std::int64_t append_admin_row(StoreTransaction& tx, const MarkContext& ctx, AuditKind kind, MarkRecord m,
                              Outcome outcome = Outcome::done) {
  m.time_utc = format_utc(ctx.now);
  m.station = ctx.station;
  m.job = ctx.job;
  m.job_sha256 = ctx.job_sha256;
  m.kind = kind;
  const std::int64_t id = tx.insert_mark(m);
  OutcomeRecord o;
  o.time_utc = m.time_utc;
  o.outcome = outcome;
  tx.insert_outcome(id, o);
  return id;
}

}  // namespace

void SerialStore::create_counter(const std::string& name, std::int64_t start, const std::string& period,
                                 const MarkContext& ctx) {
  attempt(StoreStep::allocate, [&] {
    auto tx = backend_->begin();
    if (const auto existing = tx->counter(name))
      throw InputError("serial create " + name + ": the store " + describe() + " has this counter already (next "
                       "value " + std::to_string(existing->next) + "); `marker serial set` moves it");
    CounterState s;
    s.next = start;
    s.period = period;
    tx->create_counter(name, s);
    MarkRecord m;
    m.objects = {{name, "created at " + std::to_string(start)}};
    append_admin_row(*tx, ctx, AuditKind::create, std::move(m));
    tx->commit();
    return 0;
  });
}

std::vector<std::string> SerialStore::create_missing(const std::map<std::string, CounterSpec>& counters,
                                                     const ShiftTable& shifts, const MarkContext& ctx) {
  std::vector<std::string> created;
  for (const auto& [name, spec] : counters) {
    if (backend_->begin_read()->counter(name)) continue;
    create_counter(name, spec.start, period_key(spec, ctx.now, shifts), ctx);
    created.push_back(name);
  }
  return created;
}

CounterStatus SerialStore::status(const std::string& name, const CounterSpec* spec, const ShiftTable& shifts,
                                  SysTime now) {
  CounterStatus st;
  st.name = name;
  auto rd = backend_->begin_read();
  if (auto s = rd->counter(name)) st.state = *s, st.known = true;
  if (!st.known && spec) st.state = CounterState::fresh(*spec, period_key(*spec, now, shifts));
  if (spec) {
    const PeriodChoice period = current_period(*spec, st.state, now, shifts);
    if (auto next = peek(*spec, st.state, period.period)) st.next = next->value;
  } else if (st.known && !st.state.exhausted) {
    st.next = st.state.next;
  }
  if (st.known) {
    if (auto r = rd->issued_range(name, st.state.period, st.state.cycle)) {
      st.lowest_issued = r->first;
      st.highest_issued = r->second;
    }
  }
  return st;
}

void SerialStore::set(const CounterSpec& spec, std::int64_t value, const ShiftTable& shifts, const MarkContext& ctx) {
  if (spec.beyond(value))
    throw InputError("serial set " + spec.name + " " + std::to_string(value) + ": outside the counter's range (limit " +
                     std::to_string(spec.effective_limit()) + ", never below 0)");
  attempt(StoreStep::allocate, [&] {
    auto tx = backend_->begin();
    std::optional<CounterState> state = tx->lock_counter(spec.name);
    if (!state)
      throw InputError("serial set " + spec.name + ": the store " + describe() +
                       " has no such counter: create it with `marker serial create " + spec.name + " --start " +
                       std::to_string(value) + "`");
    const PeriodChoice period = current_period(spec, *state, ctx.now, shifts);
    if (state->period != period.period) *state = CounterState::fresh(spec, period.period);
    if (auto r = tx->issued_range(spec.name, state->period, state->cycle)) {
      const bool behind = spec.step > 0 ? value <= r->second : value >= r->first;
      if (behind)
        throw InputError("serial set " + spec.name + " " + std::to_string(value) + ": refused, " +
                         std::to_string(spec.step > 0 ? r->second : r->first) +
                         " was already issued in this period (a number is never issued twice); "
                         "the next value is at least " +
                         std::to_string((spec.step > 0 ? r->second : r->first) + spec.step));
    }
    state->next = value;
    state->used = 0;
    state->exhausted = false;
    tx->update_counter(spec.name, *state);
    MarkRecord m;
    m.objects = {{spec.name, "set to " + std::to_string(value)}};
    append_admin_row(*tx, ctx, AuditKind::set, std::move(m));
    tx->commit();
    return 0;
  });
}

std::vector<Issue> SerialStore::reserve(const CounterSpec& spec, std::int64_t count, const ShiftTable& shifts,
                                        const MarkContext& ctx) {
  if (!kReserveCount.range.contains(count))
    throw InputError("serial reserve: the count must lie between " + kReserveCount.range.text() + ", got " +
                     std::to_string(count));
  return attempt(StoreStep::allocate, [&] {
    auto tx = backend_->begin();
    std::optional<CounterState> state = tx->lock_counter(spec.name);
    if (!state)
      throw PartRefused("counter \"" + spec.name + "\" is not in the serial store " + describe() +
                        ": create it with `marker serial create " + spec.name + " [--start N]`");
    const PeriodChoice period = current_period(spec, *state, ctx.now, shifts);
    std::vector<Issue> issued;
    for (std::int64_t i = 0; i < count; ++i) {
      issued.push_back(take(spec, *state, period.period));
      if (const auto owner = tx->issue_owner(issued.back()))
        throw PartRefused("serial reserve " + spec.name + ": " + std::to_string(issued.back().value) +
                          " was issued already (row " + std::to_string(*owner) +
                          "); set the counter past it with `marker serial set`");
    }
    tx->update_counter(spec.name, *state);
    for (const Issue& is : issued) {
      MarkRecord m;
      m.serials[spec.name] = is.value;
      m.note = period.stepped_back ? "clock behind the counter's period " + period.period : "";
      tx->insert_issue(is, append_admin_row(*tx, ctx, AuditKind::reserve, std::move(m), Outcome::reserved));
    }
    tx->commit();
    return issued;
  });
}

void SerialStore::read_log(const AuditFilter& filter, const std::function<bool(const AuditRow&)>& row) {
  const std::uint64_t at_start = interrupts();
  backend_->set_cancel([this, at_start] { return interrupts() != at_start; });
  backend_->begin_read()->audit(filter, row);
}

std::vector<AuditRow> SerialStore::log(const std::string& since_utc) {
  std::vector<AuditRow> rows;
  AuditFilter f;
  f.since_utc = since_utc;
  read_log(f, [&](const AuditRow& r) {
    rows.push_back(r);
    return true;
  });
  return rows;
}

std::vector<std::pair<std::string, CounterState>> SerialStore::counters() { return backend_->begin_read()->counters(); }

std::vector<std::pair<Issue, std::int64_t>> SerialStore::issues(const std::string& counter) {
  std::vector<std::pair<Issue, std::int64_t>> out;
  backend_->begin_read()->issues(counter, [&](const Issue& i, std::int64_t id) { out.emplace_back(i, id); });
  return out;
}

std::vector<std::string> SerialStore::check(bool quick) {
  std::vector<std::string> problems = backend_->check(quick);
  if (!problems.empty()) return problems;  // the rules below read what may be damaged
  auto rd = backend_->begin_read();
  for (const auto& [name, state] : rd->counters()) {
    const Issue next{name, state.next, state.used, state.period, state.cycle};
    if (const auto owner = rd->issue_owner(next))
      problems.push_back("counter \"" + name + "\": its next value " + std::to_string(state.next) +
                         " was issued already (row " + std::to_string(*owner) +
                         "): its next part would be refused; set it past its issued values with `marker serial set`");
  }
  return problems;
}

}  // namespace mark
