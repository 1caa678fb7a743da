#pragma once
// `--inject KIND@N` (marker mark): see what a fault does. underrun@N — the drain finds no
// sample from sample N on; abort@N — a stop request at sample (or device command) N; fault@N —
// the simulated scanner reports a fault of its own at sample N.
// `--inject store@STEP[:FAULT[:ATTEMPTS]]` (mark --job): the serial store fails at STEP
// (allocate, outcome) of the first part — FAULT locked (default), full, io (SQLite) or stopped
// (PostgreSQL), made to happen for real (marker/store/store_faults.hpp) — on its first ATTEMPTS
// attempts (default 0: every attempt).
#include <cstdint>
#include <optional>
#include <string>

#include "marker/job/job.hpp"
#include "marker/store/store_faults.hpp"

namespace mark::cli {

struct InjectArg {
  Injection drain;                      // underrun / abort
  std::uint64_t device_fault_at = UINT64_MAX;  // fault
  std::optional<StoreFaultPlan> store;  // store@…
};

// Throws InputError naming the option, the value and the accepted forms.
InjectArg parse_inject(const std::string& value);

}  // namespace mark::cli
