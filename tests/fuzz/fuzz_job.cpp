// Fuzz target for the job-file parser: any input either parses into a job whose invariants hold
// (objects with pens that exist, counters the templates use declared and valid) or throws
// InputError naming the file. Anything else is a bug. Parsing opens nothing and writes nothing.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "fonts/error.hpp"
#include "marker/job/job_file.hpp"

namespace {

[[noreturn]] void broken(const char* what) {
  std::fprintf(stderr, "fuzz invariant broken: %s\n", what);
  std::abort();
}

}  // namespace

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
  } catch (const mark::InputError& e) {
    if (std::string_view(e.what()).rfind("fuzz.json", 0) != 0 &&
        std::string_view(e.what()).find("fuzz.json") == std::string_view::npos)
      broken("an error that does not name the file");
  }
  return 0;
}
