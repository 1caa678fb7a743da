#pragma once
// The files a production run writes for each part (`mark --job --preview / --dose-png /
// --trace`): names that may hold {mark_id} (the part's audit-log id), {serial} (the value of the
// counter named "serial", or of the job's one counter) and {NAME} (counter NAME's value), each
// as the part's text renders it (width, padding, alphabet), so each part gets its own file.
#include <cstdint>
#include <map>
#include <string>

#include "marker/production/job_file.hpp"

namespace mark {

struct PartFile {
  std::string option;   // "--preview", for messages
  std::string pattern;  // as given
};

// Throws InputError (one line, naming the option) for a placeholder the job does not have, and
// when `parts` > 1 and no placeholder tells the parts apart ({mark_id}, or a counter whose value
// changes at every part: marks_per_serial 1) — part 2 would overwrite part 1.
void check_part_file(const PartFile& file, const JobFile& job, long long parts);

// The part's file name: every placeholder replaced (a '/' in a rendered value becomes '_').
std::string part_file_name(const PartFile& file, const JobFile& job, std::int64_t mark_id,
                           const std::map<std::string, std::int64_t>& serials);

}  // namespace mark
