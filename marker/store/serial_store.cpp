#include "marker/store/serial_store.hpp"

#include "base/error.hpp"
#include "marker/limits/production_settings.hpp"
#include "marker/store/utc_time.hpp"

namespace mark {

SerialStore::SerialStore(std::unique_ptr<StoreBackend> backend) : backend_(std::move(backend)) {}

std::vector<std::int64_t> SerialStore::start_station(const MarkContext& ctx) {
  if (!backend_->claim_station(ctx.station))
    throw StoreError("serial store " + describe() + ": station '" + ctx.station +
                     "' is marking in another process; give this one its own --station name");
  auto tx = backend_->begin();
  const std::vector<std::int64_t> pending = tx->pending_marks(ctx.station);
  for (std::int64_t id : pending) {
    OutcomeRecord o;
    o.time_utc = format_utc(ctx.now);
    o.outcome = Outcome::aborted;
    o.message = "interrupted: the marking process ended before it recorded the outcome; the "
                "numbers are void";
    tx->insert_outcome(id, o);
  }
  tx->commit();
  return pending;
}

Allocation SerialStore::allocate(const std::map<std::string, CounterSpec>& counters,
                                 const ShiftTable& shifts, const MarkContext& ctx,
                                 const RenderObjects& render) {
  Allocation a;
  a.time_utc = format_utc(ctx.now);
  auto tx = backend_->begin();
  // std::map: counters are locked in name order, so two stations never wait on each other in
  // a cycle.
  for (const auto& [name, spec] : counters) {
    const std::string period = period_key(spec, ctx.now, shifts);
    CounterState state = tx->lock_counter(name, CounterState::fresh(spec, period));
    const Issue issue = take(spec, state, period);
    tx->update_counter(name, state);
    a.serials[name] = issue.value;
    a.issues.emplace(name, issue);
  }
  a.objects = render(a.serials);
  MarkRecord m;
  m.time_utc = a.time_utc;
  m.station = ctx.station;
  m.job = ctx.job;
  m.job_sha256 = ctx.job_sha256;
  m.kind = AuditKind::mark;
  m.objects = a.objects;
  m.serials = a.serials;
  a.mark_id = tx->insert_mark(m);
  for (const auto& [name, issue] : a.issues) tx->insert_issue(issue, a.mark_id);
  tx->commit();
  return a;
}

void SerialStore::record_outcome(std::int64_t mark_id, const OutcomeRecord& outcome) {
  auto tx = backend_->begin();
  tx->insert_outcome(mark_id, outcome);
  tx->commit();
}

Allocation SerialStore::remark(std::int64_t original, const MarkContext& ctx) {
  auto tx = backend_->begin();
  const std::optional<AuditRow> row = tx->audit_row(original);
  if (!row || (row->mark.kind != AuditKind::mark && row->mark.kind != AuditKind::remark))
    throw InputError("--remark " + std::to_string(original) + ": the store " + describe() +
                     " has no mark with that id (see `marker log`)");
  if (row->mark.job_sha256 != ctx.job_sha256)
    throw InputError("--remark " + std::to_string(original) + ": that part was marked with job " +
                     row->mark.job + " (SHA-256 " + row->mark.job_sha256.substr(0, 12) +
                     "…), not with this job file");
  Allocation a;
  a.time_utc = format_utc(ctx.now);
  MarkRecord m = row->mark;
  m.time_utc = a.time_utc;
  m.station = ctx.station;
  m.job = ctx.job;
  m.kind = AuditKind::remark;
  m.remark_of = original;
  a.mark_id = tx->insert_mark(m);
  a.objects = m.objects;
  a.serials = m.serials;
  tx->commit();
  return a;
}

CounterStatus SerialStore::status(const std::string& name, const CounterSpec* spec,
                                  const ShiftTable& shifts, SysTime now) {
  CounterStatus st;
  st.name = name;
  auto tx = backend_->begin();
  for (auto& [n, s] : tx->counters())
    if (n == name) st.state = s, st.known = true;
  if (!st.known && spec) st.state = CounterState::fresh(*spec, period_key(*spec, now, shifts));
  if (spec) {
    if (auto next = peek(*spec, st.state, period_key(*spec, now, shifts))) st.next = next->value;
  } else if (st.known && !st.state.exhausted) {
    st.next = st.state.next;
  }
  if (st.known) {
    if (auto r = tx->issued_range(name, st.state.period, st.state.cycle)) {
      st.lowest_issued = r->first;
      st.highest_issued = r->second;
    }
  }
  return st;  // read only: the transaction rolls back
}

void SerialStore::set(const CounterSpec& spec, std::int64_t value, const ShiftTable& shifts,
                      const MarkContext& ctx) {
  if (spec.beyond(value))
    throw InputError("serial set " + spec.name + " " + std::to_string(value) +
                     ": outside the counter's range (limit " +
                     std::to_string(spec.effective_limit()) + ", never below 0)");
  const std::string period = period_key(spec, ctx.now, shifts);
  auto tx = backend_->begin();
  CounterState state = tx->lock_counter(spec.name, CounterState::fresh(spec, period));
  if (state.period != period) state = CounterState::fresh(spec, period);
  if (auto r = tx->issued_range(spec.name, state.period, state.cycle)) {
    const bool behind = spec.step > 0 ? value <= r->second : value >= r->first;
    if (behind)
      throw InputError("serial set " + spec.name + " " + std::to_string(value) + ": refused, " +
                       std::to_string(spec.step > 0 ? r->second : r->first) +
                       " was already issued in this period (a number is never issued twice); "
                       "the next value is at least " +
                       std::to_string((spec.step > 0 ? r->second : r->first) + spec.step));
  }
  state.next = value;
  state.used = 0;
  state.exhausted = false;
  tx->update_counter(spec.name, state);
  MarkRecord m;
  m.time_utc = format_utc(ctx.now);
  m.station = ctx.station;
  m.job = ctx.job;
  m.job_sha256 = ctx.job_sha256;
  m.kind = AuditKind::set;
  m.objects = {{spec.name, "set to " + std::to_string(value)}};
  const std::int64_t id = tx->insert_mark(m);
  OutcomeRecord o;
  o.time_utc = m.time_utc;
  tx->insert_outcome(id, o);
  tx->commit();
}

std::vector<Issue> SerialStore::reserve(const CounterSpec& spec, std::int64_t count,
                                        const ShiftTable& shifts, const MarkContext& ctx) {
  if (!kReserveCount.range.contains(count))
    throw InputError("serial reserve: the count must lie between " + kReserveCount.range.text() + ", got " +
                     std::to_string(count));
  const std::string period = period_key(spec, ctx.now, shifts);
  auto tx = backend_->begin();
  CounterState state = tx->lock_counter(spec.name, CounterState::fresh(spec, period));
  std::vector<Issue> issued;
  for (std::int64_t i = 0; i < count; ++i) issued.push_back(take(spec, state, period));
  tx->update_counter(spec.name, state);
  for (const Issue& is : issued) {
    MarkRecord m;
    m.time_utc = format_utc(ctx.now);
    m.station = ctx.station;
    m.job = ctx.job;
    m.job_sha256 = ctx.job_sha256;
    m.kind = AuditKind::reserve;
    m.serials[spec.name] = is.value;
    const std::int64_t id = tx->insert_mark(m);
    tx->insert_issue(is, id);
    OutcomeRecord o;
    o.time_utc = m.time_utc;
    o.outcome = Outcome::reserved;
    tx->insert_outcome(id, o);
  }
  tx->commit();
  return issued;
}

std::vector<AuditRow> SerialStore::log(const std::string& since_utc) {
  return backend_->begin()->audit(since_utc);
}

std::vector<std::pair<std::string, CounterState>> SerialStore::counters() {
  return backend_->begin()->counters();
}

std::vector<std::pair<Issue, std::int64_t>> SerialStore::issues(const std::string& counter) {
  return backend_->begin()->issues(counter);
}

}  // namespace mark
