// libFuzzer target for the per-part file names of `mark --job --preview/--dose-png/--trace`
// (marker/production/part_files.hpp): the input is a name pattern. It is either refused with an
// InputError or every placeholder is replaced (no '{' is left), and a pattern accepted for two
// parts gives two parts with different ids and serials different names (part 2 never overwrites
// part 1).
#include <cstdint>
#include <string>

#include "base/error.hpp"
#include "marker/production/part_files.hpp"
#include "tests/fuzz/fuzz_check.hpp"

namespace {

const mark::JobFile& job() {
  static const mark::JobFile j = mark::parse_job(R"({
    "format": "marker-job/1", "head": "SL10",
    "counters": {"serial": {"start": 41, "width": 6}, "lot": {"start": 7, "marks_per_serial": 3}},
    "pens": {"p": {"speed_mm_s": 800}},
    "objects": [{"name": "a", "pen": "p", "template": "SN {serial} L{lot}", "height_mm": 3}]
  })", "fuzz.json");
  return j;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const mark::PartFile file{"--preview", std::string(reinterpret_cast<const char*>(data), size)};
  try {
    mark::check_part_file(file, job(), 2);
  } catch (const mark::InputError&) {
    return 0;
  }
  const std::string one = mark::part_file_name(file, job(), 2, {{"serial", 41}, {"lot", 7}});
  const std::string two = mark::part_file_name(file, job(), 3, {{"serial", 42}, {"lot", 7}});
  if (one.find('{') != std::string::npos) mark::fuzz::broken("a placeholder was left in a part's file name");
  if (one == two) mark::fuzz::broken("a name accepted for two parts gives both parts the same file");
  return 0;
}
