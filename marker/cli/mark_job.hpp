#pragma once
// `marker mark --job FILE [--set NAME=VALUE …] [--count N] [--store PATH|URL] [--station NAME]
//  [--remark ID] [--device D] [--inject KIND@N] [--virtual-time] [--json]`: the production
// run — N parts in a row, each with its next serial numbers (marker/production/part_run.hpp), one line
// or one JSON object (JSON Lines) per part. The run stops at the first part that does not end
// done: Ctrl-C finishes that part with the laser off where it stopped, records it aborted and
// exits 130; a failed part exits 1.
#include <optional>
#include <string>
#include <vector>

namespace mark::cli {

struct MarkJobArgs {
  std::string job;
  std::vector<std::string> sets;
  long long count = 1;
  std::string store;
  std::string station;
  std::optional<long long> remark;
  std::string device;  // empty: the job's
  std::string inject;
  bool virtual_time = false;
  bool json = false;
};

int run_mark_job(const MarkJobArgs& args);

}  // namespace mark::cli
