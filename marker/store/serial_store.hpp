#pragma once
// The serial store: never repeat a number, never lose one. One part's life:
//
//   allocate()        one transaction: lock the job's counters (in name order), take() the next
//                     value of each, write them back, record every value consumed and the audit
//                     row with the rendered texts — committed durably before it returns, so
//                     before the first sample reaches the device;
//   (the mark runs)
//   record_outcome()  done, aborted or failed, with the device's figures. An aborted or failed
//                     part's numbers are void: the counters have moved past them for good.
//
// A process that dies between the two leaves a row without an outcome; the next start of that
// station (start_station) records it as aborted. A re-mark of a part is its own audit row that
// links the first and consumes no number.
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "marker/store/store_backend.hpp"
#include "marker/vars/counter.hpp"
#include "marker/vars/shifts.hpp"

namespace mark {

// Who marks what, when.
struct MarkContext {
  std::string station = "station";
  std::string job;         // path as given
  std::string job_sha256;
  SysTime now{};
};

struct Allocation {
  std::int64_t mark_id = 0;
  std::map<std::string, Issue> issues;  // by counter name
  std::map<std::string, std::int64_t> serials;
  std::vector<ObjectText> objects;
  std::string time_utc;
};

// Renders every object's text from the values a part consumed. Called inside the allocation
// transaction: if it throws, nothing is consumed and nothing is logged.
using RenderObjects =
    std::function<std::vector<ObjectText>(const std::map<std::string, std::int64_t>& serials)>;

struct CounterStatus {
  std::string name;
  CounterState state;                 // as stored
  std::optional<std::int64_t> next;   // what the next part gets (with a spec: after the reset
                                      // and limit rules; nothing when the counter has stopped)
  std::optional<std::int64_t> highest_issued;  // in the current period and cycle
  std::optional<std::int64_t> lowest_issued;
  bool known = false;                 // the store has seen this counter
};

class SerialStore {
 public:
  explicit SerialStore(std::unique_ptr<StoreBackend> backend);

  const StoreBackend& backend() const { return *backend_; }
  std::string describe() const { return backend_->describe(); }

  // Claims the station name (throws StoreError if another process marks as this station on
  // this store) and closes the rows a dead process of this station left open: outcome
  // aborted, numbers void. Returns their ids.
  std::vector<std::int64_t> start_station(const MarkContext& ctx);

  // The counters a part consumes (each once, whatever the number of fields using it).
  Allocation allocate(const std::map<std::string, CounterSpec>& counters, const ShiftTable& shifts,
                      const MarkContext& ctx, const RenderObjects& render);
  void record_outcome(std::int64_t mark_id, const OutcomeRecord& outcome);
  // A new audit row with the texts and values of `original` (which must be a mark or re-mark
  // of this store), linked to it. Consumes no number.
  Allocation remark(std::int64_t original, const MarkContext& ctx);

  // With a spec, `next` follows its rules at ctx.now; without, it is the stored next value.
  CounterStatus status(const std::string& name, const CounterSpec* spec, const ShiftTable& shifts,
                       SysTime now);
  // Makes `value` the next value of the counter (in the current period and cycle). Refused
  // (InputError) when a value at or past it in counting direction was issued there already.
  void set(const CounterSpec& spec, std::int64_t value, const ShiftTable& shifts,
           const MarkContext& ctx);
  // Issues `count` values without marking (labels printed elsewhere, a spare station). One
  // audit row per value, outcome reserved.
  std::vector<Issue> reserve(const CounterSpec& spec, std::int64_t count, const ShiftTable& shifts,
                             const MarkContext& ctx);

  std::vector<AuditRow> log(const std::string& since_utc = "");
  std::vector<std::pair<std::string, CounterState>> counters();
  std::vector<std::pair<Issue, std::int64_t>> issues(const std::string& counter);

 private:
  std::unique_ptr<StoreBackend> backend_;
};

}  // namespace mark
