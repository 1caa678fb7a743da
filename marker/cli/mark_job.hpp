#pragma once
// `marker mark --job FILE [--set NAME=VALUE …] [--count N] [--store PATH|URL] [--station NAME]
//  [--create-counters] [--remark ID [--reason TEXT]] [--device D] [--inject KIND@N]
//  [--virtual-time] [--json] [--preview F.png|svg] [--dose-png F.png] [--trace F.csv]`: the production run — N parts in a row, each with its next serial
// numbers (marker/production/part_run.hpp), one line or one JSON object (JSON Lines) per part,
// into the station's serial store (or --store). The run stops at the first part that does not
// end done: Ctrl-C finishes that part with the laser off where it stopped, records it aborted
// and exits 130; a failed part exits 1. A part whose outcome the store did not take still gets
// its line (the outcome waits in the station's journal); if not even the journal took it the
// run stops with exit 1. --preview, --dose-png and --trace write each part's files (all its
// objects on one picture) after its outcome is recorded; a file that cannot be written is named
// in the part's line and stops the run with exit 1, the part's outcome as recorded.
#include <optional>
#include <string>
#include <vector>

#include "marker/cli/production_options.hpp"
#include "marker/production/job_file.hpp"

namespace mark::cli {

struct MarkJobArgs {
  std::string job;
  std::vector<std::string> sets;
  long long count = 1;
  StoreArgs store;
  std::string station;
  bool create_counters = false;
  std::optional<long long> remark;
  std::string reason;
  bool allow_changed_job = false;
  std::string device;  // empty: the job's
  std::string inject;
  bool virtual_time = false;
  bool json = false;
  // Each part's pictures and trace (simulated scanner only): names with {mark_id}, {serial},
  // {COUNTER} (marker/production/part_files.hpp); empty: not written.
  std::string preview;
  std::string dose_png;
  std::string trace;
};

int run_mark_job(const MarkJobArgs& args);

// The station's start (also `marker serve`'s): its journal replayed, rows a dead run left open
// closed, counters the store lacks created (--create-counters) or refused with the command that
// creates them; what it did on stderr.
void start_station(SerialStore& store, const MarkContext& context, const JobFile& job, const MarkJobArgs& a);

// "counter \"sn\" is not in the serial store S: create it with `marker serial create …`": what
// `mark --job` refuses with and `job new` warns of.
std::string counter_not_in_store(const std::string& job_path, const std::string& name, const CounterSpec& spec,
                                 const std::string& store);

}  // namespace mark::cli
