// Fuzz target for the job-file parser: any input either parses into a job whose invariants hold
// (objects with pens that exist and that the planner accepts for the job's head, counters the
// templates use declared and valid, a first part that renders one text per object) or throws
// InputError naming the file. Anything else is a bug. Parsing opens nothing and writes nothing.
#include <cstdint>
#include <string_view>

#include "base/error.hpp"
#include "fuzz_check.hpp"
#include "marker/job/job_checks.hpp"
#include "marker/production/job_file.hpp"
#include "marker/production/part_texts.hpp"

using mark::fuzz::broken;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const mark::JobFile job = mark::parse_job(text, "fuzz.json");
    if (job.objects.empty() || job.pens.empty()) broken("a job without objects or pens");
    for (const mark::JobObject& o : job.objects) {
      if (!job.pens.count(o.pen)) broken("an object's pen does not exist");
      if (const mark::TextObject* t = o.text())
        for (const std::string& c : t->text.counters()) {
          if (!job.counters.count(c)) broken("a template uses an undeclared counter");
          job.counters.at(c).validate("fuzz");  // must not throw: checked while parsing
        }
    }
    // A pen the parser accepts is one the planner accepts: `job check` and `mark` never refuse
    // what reading the job let through (this would throw an error without the file's name).
    for (const auto& [name, pen] : job.pens) mark::check_pen(pen.motion, job.head);
    // The first part renders (dates at a fixed instant, every counter at its start).
    const mark::SysTime t{std::chrono::seconds(1'790'000'000)};
    if (mark::first_part_texts(job, job.variables, t).size() != job.objects.size())
      broken("a part's texts do not match the job's objects");
  } catch (const mark::InputError& e) {
    if (std::string_view(e.what()).rfind("fuzz.json", 0) != 0 &&
        std::string_view(e.what()).find("fuzz.json") == std::string_view::npos)
      broken("an error that does not name the file");
  }
  return 0;
}
