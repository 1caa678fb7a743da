#include "marker/production/part_files.hpp"

#include <functional>

#include "base/error.hpp"

namespace mark {
namespace {

constexpr const char* kMarkId = "mark_id";
constexpr const char* kSerial = "serial";

// The counter a placeholder names ({serial}: the counter "serial", or the job's only counter);
// nullptr for {mark_id}. Throws for one the job does not have.
const CounterSpec* placeholder_counter(const PartFile& file, const JobFile& job, const std::string& name) {
  if (name == kMarkId) return nullptr;
  const auto used = job.used_counters();
  if (const auto it = job.counters.find(name); it != job.counters.end() && used.count(name)) return &it->second;
  if (name == kSerial && used.size() == 1) return &job.counters.at(used.begin()->first);
  std::string names = std::string("{") + kMarkId + "}";
  if (used.size() == 1 && !used.count(kSerial)) names += std::string(", {") + kSerial + "}";
  for (const auto& [n, spec] : used) names += ", {" + n + "}";
  throw InputError(file.option + " '" + file.pattern + "': {" + name + "} is not a placeholder of this job: use " +
                   names);
}

// Calls `field` with each placeholder's name, in order; text between them to `text`.
void scan(const PartFile& file, const std::function<void(const std::string&)>& text,
          const std::function<void(const std::string&)>& field) {
  const std::string& p = file.pattern;
  std::size_t pos = 0;
  while (pos < p.size()) {
    const std::size_t open = p.find('{', pos);
    if (open == std::string::npos) {
      text(p.substr(pos));
      return;
    }
    const std::size_t close = p.find('}', open);
    if (close == std::string::npos)
      throw InputError(file.option + " '" + p + "': '{' at character " + std::to_string(open + 1) +
                       " is not closed: placeholders are {mark_id}, {serial} or {COUNTER}");
    text(p.substr(pos, open - pos));
    field(p.substr(open + 1, close - open - 1));
    pos = close + 1;
  }
}

}  // namespace

void check_part_file(const PartFile& file, const JobFile& job, long long parts) {
  bool distinct = false;
  scan(file, [](const std::string&) {}, [&](const std::string& name) {
    const CounterSpec* counter = placeholder_counter(file, job, name);
    distinct = distinct || !counter || counter->marks_per_serial == 1;
  });
  if (parts > 1 && !distinct)
    throw InputError(file.option + " '" + file.pattern + "': " + std::to_string(parts) +
                     " parts would write the same file: put {mark_id} or {serial} in the name (docs/job-file.md)");
}

std::string part_file_name(const PartFile& file, const JobFile& job, std::int64_t mark_id,
                           const std::map<std::string, std::int64_t>& serials) {
  std::string out;
  scan(file, [&](const std::string& t) { out += t; }, [&](const std::string& name) {
    const CounterSpec* counter = placeholder_counter(file, job, name);
    std::string value;
    if (!counter) {
      value = std::to_string(mark_id);
    } else if (const auto it = serials.find(counter->name); it != serials.end()) {
      counter->format(it->second, value);
    }
    for (char& c : value)
      if (c == '/' || c == '\\') c = '_';
    out += value;
  });
  return out;
}

}  // namespace mark
