#pragma once
// What the serial store records. The audit log is append-only: one row per mark (or re-mark,
// reservation, counter set), written in the allocation transaction before the laser fires,
// and one outcome per row, written once afterwards. A row without an outcome belongs to a mark
// still running — or to a process that died; the next start of that station closes it as
// aborted, and its numbers stay void.
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "marker/vars/counter.hpp"

namespace mark {

// rejected: marked to the end, but its verification failed (a code not read back): scrap, its
// numbers void like an aborted part's.
enum class Outcome { done, aborted, failed, reserved, rejected };

std::string_view to_string(Outcome o);
std::optional<Outcome> parse_outcome(std::string_view name);

// What kind of row: a part marked, a part marked again (remark_of links the first), numbers
// reserved without marking, a counter set by hand.
// A counter created (`serial create`, `mark --create-counters`).
enum class AuditKind { mark, remark, reserve, set, create };

std::string_view to_string(AuditKind k);
std::optional<AuditKind> parse_audit_kind(std::string_view name);

struct ObjectText {
  std::string name;
  std::string text;
  // The text carries a serial field: the store refuses a part whose such text was marked
  // before (the marked-text index; not written into the audit row's JSON).
  bool unique = false;
};

// The row written at allocation.
struct MarkRecord {
  std::string time_utc;
  std::string station;
  std::string job;         // the job file's path as given
  std::string job_sha256;  // of its bytes
  AuditKind kind = AuditKind::mark;
  std::optional<std::int64_t> remark_of;
  std::vector<ObjectText> objects;     // every object's rendered text, in job order
  std::map<std::string, std::int64_t> serials;  // counter values consumed
  std::string reason;      // a re-mark's reason (--reason)
  std::string note;        // what the store noticed (a clock stepped back)
  std::string data_list;   // the data list a row was taken from (file as given), or empty
  std::optional<std::int64_t> data_row;  // its row number (1: the first row after the header)
};

// The row written afterwards.
struct OutcomeRecord {
  std::string time_utc;
  Outcome outcome = Outcome::done;
  std::string message;                 // the fault or abort reason; empty when done
  nlohmann::json figures = nlohmann::json::object();  // the device's figures, the quality
};

struct AuditRow {
  std::int64_t id = 0;
  MarkRecord mark;
  std::optional<OutcomeRecord> outcome;  // nothing: pending
  // The values consumed with their period and cycle (a re-mark: its original's), so a value
  // issued again after a reset or a wrap is not read as a repeat.
  std::vector<Issue> issues;

  // The objects' texts joined by new lines (one object: its text).
  std::string text() const;
};

}  // namespace mark
