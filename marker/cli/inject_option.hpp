#pragma once
// `--inject KIND@N` (marker mark): see what a fault does. underrun@N — the drain finds no
// sample from sample N on; abort@N — a stop request at sample (or device command) N; fault@N —
// the simulated scanner reports a fault of its own at sample N.
#include <cstdint>
#include <string>

#include "marker/job/job.hpp"

namespace mark::cli {

struct InjectArg {
  Injection drain;                      // underrun / abort
  std::uint64_t device_fault_at = UINT64_MAX;  // fault
};

// Throws InputError naming the option, the value and the accepted forms.
InjectArg parse_inject(const std::string& value);

}  // namespace mark::cli
