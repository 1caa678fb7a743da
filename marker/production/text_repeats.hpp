#pragma once
// What `marker job check` warns about before a line runs into it: objects whose texts repeat —
// and so are refused by the store's marked-text index, part after part — because a counter
// they carry restarts (at midnight, at each shift start) or wraps at its limit while nothing
// else in the text names the day (or the shift) it restarted for.
#include <string>
#include <vector>

#include "marker/production/job_file.hpp"

namespace mark {

// One line per (object, counter) that would repeat, "job.json: objects[0] "serial": …".
std::vector<std::string> text_repeat_warnings(const JobFile& job);

}  // namespace mark
