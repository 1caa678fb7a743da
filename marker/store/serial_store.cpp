#include "marker/store/serial_store.hpp"

#include <chrono>
#include <set>
#include <thread>

#include "base/error.hpp"
#include "marker/store/digest.hpp"
#include "marker/store/utc_time.hpp"

namespace mark {
namespace {

std::string joined_text(const std::vector<ObjectText>& objects) {
  std::string t;
  for (std::size_t i = 0; i < objects.size(); ++i) t.append(i ? "\n" : "").append(objects[i].text);
  return t;
}

// "row 17 (2026-03-05T09:41:00.000000Z, station line-1, job part.json, done)"
std::string row_summary(const std::optional<AuditRow>& r, std::int64_t id) {
  std::string s = "row " + std::to_string(id);
  if (!r) return s;
  return s + " (" + r->mark.time_utc + ", station " + r->mark.station + ", job " + r->mark.job + ", " +
         (r->outcome ? std::string(to_string(r->outcome->outcome)) : std::string("pending")) + ")";
}

// The first data-list row from `data.from` on that no part has taken (its identity in `key`);
// nothing when every one is taken.
std::optional<std::size_t> first_free_row(StoreReader& rd, const DataPick& data, std::string* key) {
  for (std::size_t i = data.from; i < data.list->size(); ++i) {
    std::string k = sha256_hex(data.list->identity(i));
    if (rd.data_row_owner(k)) continue;
    if (key) *key = std::move(k);
    return i;
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::size_t> SerialStore::next_data_row(const DataPick& data) {
  return first_free_row(*backend_->begin_read(), data, nullptr);
}

SerialStore::SerialStore(std::unique_ptr<StoreBackend> backend, StoreSettings settings)
    : backend_(std::move(backend)), settings_(std::move(settings)) {}

SerialStore::~SerialStore() = default;

std::uint64_t SerialStore::interrupts() const { return settings_.interrupts ? settings_.interrupts() : 0; }

void SerialStore::pause(int attempt, std::uint64_t at_start) {
  long long ms = settings_.retry.first_delay_ms;
  for (int i = 1; i < attempt && ms < settings_.retry.max_delay_ms; ++i) ms *= 2;
  ms = std::min<long long>(ms, settings_.retry.max_delay_ms);
  const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(ms);
  while (std::chrono::steady_clock::now() < until && interrupts() == at_start)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

void SerialStore::run_step(StoreStep step, const std::function<void()>& once) {
  const int call = ++calls_[step];
  const std::uint64_t at_start = interrupts();
  backend_->set_cancel([this, at_start] { return interrupts() != at_start; });
  const StoreFaultPlan* plan = settings_.fault && settings_.fault->step == step && settings_.fault->part == call
                                   ? &*settings_.fault
                                   : nullptr;
  for (int n = 1;; ++n) {
    const bool faulty = plan && (plan->attempts == 0 || n <= plan->attempts);
    try {
      // The fault lasts for this attempt only; the next one finds the store as it is.
      struct Heal {
        StoreBackend* b;
        ~Heal() {
          if (b) b->heal();
        }
      } heal{faulty ? backend_.get() : nullptr};
      if (faulty) backend_->provoke(step, plan->kind);
      once();
      return;
    } catch (const StoreError& e) {
      // An allocation is tried again only where waiting may help (a lock, a connection); an
      // outcome whatever the store said, except a refusal by a key or a cancel.
      const bool again = step == StoreStep::allocate
                             ? e.transient()
                             : e.kind() != StoreErrorKind::cancelled && e.kind() != StoreErrorKind::constraint;
      if (!again || n >= settings_.retry.attempts || interrupts() != at_start) throw;
      if (e.kind() == StoreErrorKind::connection) {
        try {
          backend_->reconnect();
        } catch (const StoreError&) {
          // still down: the next attempt says so, or the last one does
        }
      }
    }
    pause(n, at_start);
    if (interrupts() != at_start)
      throw StoreError("serial store " + describe() + ": cancelled while waiting to try again",
                       StoreErrorKind::cancelled);
  }
}

StationStart SerialStore::start_station(const MarkContext& ctx) {
  if (!backend_->claim_station(ctx.station))
    throw StoreError("serial store " + describe() + ": station '" + ctx.station +
                         "' is marking in another process on this store; give this one its own --station name",
                     StoreErrorKind::busy);
  const std::vector<std::string> problems = backend_->check(true);
  if (!problems.empty())
    throw StoreError("serial store " + describe() + " is damaged (quick_check: " + problems.front() +
                         (problems.size() > 1 ? "; " + std::to_string(problems.size() - 1) + " more" : "") +
                         "): refused — restore the last backup (`marker store backup` makes them), docs/store.md",
                     StoreErrorKind::corrupt);
  StationStart s;
  if (!settings_.journal_dir.empty())
    journal_ = std::make_unique<OutcomeJournal>(settings_.journal_dir, backend_->store_id(), ctx.station);
  s.replayed = replay(&s.notes);
  auto tx = backend_->begin();
  s.closed = tx->pending_marks(ctx.station);
  for (std::int64_t id : s.closed) {
    OutcomeRecord o;
    o.time_utc = format_utc(ctx.now);
    o.outcome = Outcome::aborted;
    o.message = "interrupted: the marking process ended before it recorded the outcome; the numbers are void";
    tx->insert_outcome(id, o);
  }
  tx->commit();
  return s;
}

std::vector<std::int64_t> SerialStore::replay(std::vector<std::string>* notes) {
  std::vector<std::int64_t> replayed;
  if (!journal_) return replayed;
  for (const JournalEntry& e : journal_->pending()) {
    auto tx = backend_->begin();
    const std::optional<AuditRow> row = tx->audit_row(e.mark_id);
    const std::string keep = "; its outcome (" + std::string(to_string(e.outcome.outcome)) +
                             ") stays in the journal " + journal_->path();
    if (!row) {
      if (notes) notes->push_back("outcome journal: row " + std::to_string(e.mark_id) + " is not in this store" + keep);
      continue;
    }
    if (row->outcome) {  // applied before the journal heard of it
      journal_->applied(e.mark_id);
      continue;
    }
    if (!e.serials.empty() && (row->mark.serials != e.serials || row->text() != e.text)) {
      if (notes)
        notes->push_back("outcome journal: row " + std::to_string(e.mark_id) + " of this store is another part (\"" +
                         row->text() + "\", not \"" + e.text + "\")" + keep);
      continue;
    }
    tx->insert_outcome(e.mark_id, e.outcome);
    tx->commit();
    journal_->applied(e.mark_id);
    replayed.push_back(e.mark_id);
  }
  return replayed;
}

Allocation SerialStore::allocate(const std::map<std::string, CounterSpec>& counters, const ShiftTable& shifts,
                                 const MarkContext& ctx, const RenderObjects& render) {
  return allocate(counters, shifts, ctx, DataPick{}, [&](const PartValues& v) { return render(v.serials); });
}

Allocation SerialStore::allocate(const std::map<std::string, CounterSpec>& counters, const ShiftTable& shifts,
                                 const MarkContext& ctx, const DataPick& data, const RenderPart& render) {
  if (journal_ && !journal_->empty()) {
    try {
      replay(nullptr);
    } catch (const StoreError&) {
      // the store is not taking writes yet: the allocation below says so
    }
  }
  return attempt(StoreStep::allocate, [&] {
    Allocation a;
    a.time_utc = format_utc(ctx.now);
    SysTime dated = ctx.now;
    auto tx = backend_->begin();
    // std::map: counters are locked in name order, so two stations never wait on each other
    // in a cycle.
    for (const auto& [name, spec] : counters) {
      std::optional<CounterState> state = tx->lock_counter(name);
      if (!state)
        throw PartRefused("counter \"" + name + "\" is not in the serial store " + describe() +
                          ": create it with `marker serial create " + name +
                          " [--start N]` (or mark with --create-counters)");
      const PeriodChoice period = current_period(spec, *state, ctx.now, shifts);
      if (period.stepped_back) {
        const std::optional<SysTime> start = period_start(spec, period.period, shifts);
        if (start && *start > dated) dated = *start;
        a.note += std::string(a.note.empty() ? "" : "; ") + "clock behind counter \"" + name + "\": " +
                  a.time_utc + " lies in period " + period.clock_period + ", the counter counts in " +
                  period.period + " already and stays there (periods only move forward); the part is dated " +
                  format_utc(dated);
      }
      const Issue issue = take(spec, *state, period.period);
      if (const auto owner = tx->issue_owner(issue))
        throw PartRefused("counter \"" + name + "\" would issue " + std::to_string(issue.value) + " again (period '" +
                          issue.period + "', cycle " + std::to_string(issue.cycle) + "): " +
                          row_summary(tx->audit_row(*owner), *owner) +
                          " has it; the counter stands behind its issued values — set it past them with "
                          "`marker serial set " + name + " N`");
      tx->update_counter(name, *state);
      a.serials[name] = issue.value;
      a.issues.emplace(name, issue);
    }
    PartValues values{a.serials, std::nullopt, dated};
    std::string row_key;
    if (data.list) {
      tx->lock_data_list(data.name);
      values.data_row = first_free_row(*tx, data, &row_key);
      if (!values.data_row)
        throw PartRefused("data list " + data.name + ": every row" +
                          (data.from ? " from row " + std::to_string(data.from + 1) + " on" : std::string()) +
                          " was taken by an earlier part (" + std::to_string(data.list->size()) +
                          " rows in the file): add rows to the list");
    }
    a.data_row = values.data_row;
    a.objects = render(values);
    // The marked-text index: a text that carries a serial field is marked once, whatever
    // happened to the counters (a wrap, a reset without a date, a counter re-created).
    std::vector<const ObjectText*> unique;
    std::set<std::string> seen;
    for (const ObjectText& o : a.objects) {
      if (!o.unique || !seen.insert(o.text).second) continue;
      if (const auto owner = tx->text_owner(o.text))
        throw PartRefused("part refused before marking: object \"" + o.name + "\" would mark \"" + o.text +
                          "\", which " + row_summary(tx->audit_row(*owner), *owner) +
                          " marked; a marked text is never marked again (a re-mark of that part: --remark " +
                          std::to_string(*owner) + "); set the counter past it or add a date field");
      unique.push_back(&o);
    }
    MarkRecord m;
    m.time_utc = a.time_utc;
    m.station = ctx.station;
    m.job = ctx.job;
    m.job_sha256 = ctx.job_sha256;
    m.kind = AuditKind::mark;
    m.objects = a.objects;
    m.serials = a.serials;
    m.note = a.note;
    if (values.data_row) {
      m.data_list = data.name;
      m.data_row = static_cast<std::int64_t>(*values.data_row) + 1;
    }
    a.mark_id = tx->insert_mark(m);
    for (const auto& [name, issue] : a.issues) tx->insert_issue(issue, a.mark_id);
    for (const ObjectText* o : unique) tx->insert_text(o->text, o->name, a.mark_id);
    if (values.data_row) tx->insert_data_row(row_key, data.name, *m.data_row, a.mark_id);
    tx->commit();
    open_rows_[a.mark_id] = JournalEntry{a.mark_id, {}, a.serials, joined_text(a.objects)};
    return a;
  });
}

OutcomeWrite SerialStore::record_outcome(std::int64_t mark_id, const OutcomeRecord& outcome) {
  OutcomeWrite w;
  JournalEntry entry{mark_id, outcome, {}, {}};
  if (const auto it = open_rows_.find(mark_id); it != open_rows_.end()) {
    entry.serials = it->second.serials;
    entry.text = it->second.text;
    open_rows_.erase(it);
  }
  std::string journal_error;
  if (journal_) {
    try {
      journal_->append(entry);
      w.journaled = true;
      w.journal = journal_->path();
    } catch (const StoreError& e) {
      journal_error = e.what();
    }
  }
  StoreErrorKind kind = StoreErrorKind::other;
  try {
    attempt(StoreStep::outcome, [&] {
      ++w.attempts;
      auto tx = backend_->begin();
      tx->insert_outcome(mark_id, outcome);
      tx->commit();
      return 0;
    });
    w.stored = true;
  } catch (const StoreError& e) {
    w.error = e.what();
    kind = e.kind();
    if (kind == StoreErrorKind::constraint) {
      // A commit whose answer was lost (a connection dropped after COMMIT) and tried again:
      // the store has the row's outcome already — if it is this one, it is recorded.
      try {
        const auto row = backend_->begin_read()->audit_row(mark_id);
        w.stored = row && row->outcome && row->outcome->outcome == outcome.outcome &&
                   row->outcome->time_utc == outcome.time_utc;
      } catch (const StoreError&) {
      }
    }
  }
  if (w.stored) {
    if (w.journaled) {
      try {
        journal_->applied(mark_id);
      } catch (const StoreError&) {
        // a replay finds the outcome in the store and skips it
      }
    }
    w.error.clear();
    return w;
  }
  if (w.journaled) return w;
  throw StoreError("the outcome of row " + std::to_string(mark_id) + " (" + std::string(to_string(outcome.outcome)) +
                       ") was not recorded: " + w.error + "; " +
                       (journal_error.empty() ? std::string("no outcome journal") : journal_error) +
                       " — the station's next start records the row aborted",
                   kind);
}

Allocation SerialStore::remark(std::int64_t original, const MarkContext& ctx, const std::string& reason,
                               bool allow_changed_job) {
  return attempt(StoreStep::allocate, [&] {
    auto tx = backend_->begin();
    std::optional<AuditRow> row = tx->audit_row(original);
    if (!row || (row->mark.kind != AuditKind::mark && row->mark.kind != AuditKind::remark))
      throw InputError("--remark " + std::to_string(original) + ": the store " + describe() +
                       " has no mark with that id (see `marker log`)");
    const bool job_changed = row->mark.job_sha256 != ctx.job_sha256;
    if (job_changed && !allow_changed_job)
      throw InputError("--remark " + std::to_string(original) + ": that part was marked with job " + row->mark.job +
                       " (SHA-256 " + row->mark.job_sha256.substr(0, 12) +
                       "…), not with this job file (to re-mark it with this one: --allow-changed-job, which the "
                       "audit log notes)");
    const std::string marked_with = row->mark.job + " (SHA-256 " + row->mark.job_sha256.substr(0, 12) + "…)";
    // The part is its first mark: a re-mark of a re-mark links that one.
    for (int up = 0; row->mark.kind == AuditKind::remark && row->mark.remark_of && up < 64; ++up) {
      std::optional<AuditRow> first = tx->audit_row(*row->mark.remark_of);
      if (!first) break;
      row = std::move(first);
    }
    const std::vector<RemarkRow> remarks = tx->remarks_of(row->id);
    bool done = row->outcome && row->outcome->outcome == Outcome::done;
    for (const RemarkRow& r : remarks) done = done || r.outcome == Outcome::done;
    if (done && !remarks.empty() && reason.empty())
      throw InputError("--remark " + std::to_string(original) + ": part " + std::to_string(row->id) + " (\"" +
                       row->text() + "\") was marked done and re-marked already (row " +
                       std::to_string(remarks.back().id) +
                       "); a further re-mark needs --reason TEXT, which the audit log keeps");
    Allocation a;
    a.time_utc = format_utc(ctx.now);
    MarkRecord m = row->mark;
    m.time_utc = a.time_utc;
    m.station = ctx.station;
    m.job = ctx.job;
    m.kind = AuditKind::remark;
    m.remark_of = row->id;
    m.reason = reason;
    m.note.clear();
    if (job_changed) {
      // The row says which job marked it; the note keeps the one the part was first marked with.
      m.job_sha256 = ctx.job_sha256;
      m.note = "job changed since the part was marked with " + marked_with;
    }
    a.mark_id = tx->insert_mark(m);
    a.objects = m.objects;
    a.serials = m.serials;
    if (m.data_row) a.data_row = static_cast<std::size_t>(*m.data_row - 1);
    a.remark_of = row->id;
    tx->commit();
    open_rows_[a.mark_id] = JournalEntry{a.mark_id, {}, a.serials, joined_text(a.objects)};
    return a;
  });
}

}  // namespace mark
