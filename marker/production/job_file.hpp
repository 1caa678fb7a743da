#pragma once
// A job file ("format": "marker-job/1"): named objects marked in file order, each with a named
// pen; the head, device and field; counters, variables, shifts and the time zone of the
// variable text. docs/job-file.md describes every key. Reading a job never writes anything and
// opens nothing but the file: fonts are opened when the job is compiled.
#include <map>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "driver/device.hpp"
#include "driver/sim/head_model.hpp"
#include "marker/codes/code_object.hpp"
#include "marker/fill/fill_options.hpp"
#include "marker/job/mark_requirement.hpp"
#include "marker/layout/layout.hpp"
#include "marker/plan/pen.hpp"
#include "marker/plan/stroke_order.hpp"
#include "marker/vars/counter.hpp"
#include "marker/vars/date_codes.hpp"
#include "marker/vars/shifts.hpp"
#include "marker/vars/text_template.hpp"
#include "marker/vars/time_zone.hpp"

namespace mark {

inline constexpr std::string_view kJobFormat = "marker-job/1";

// A pen: the planner's motion settings (defaults from the head, see pen_for_head) and the
// laser source's settings, marked `passes` times.
struct JobPen {
  std::string name;
  Pen motion;
  LaserSettings laser;
  int passes = 1;
};

// Text with every layout option of the command line and a template; outline-font text may be
// hatch-filled ("fill").
struct TextObject {
  TextTemplate text;
  std::string font = "builtin";
  LayoutOptions layout;
  StrokeOrder order = StrokeOrder::glyph;
  std::optional<FillOptions> fill;
};

// A 2-D code or barcode whose data is a template: a UDI code carries the same serial as the
// text beside it, from the same allocation. `code.spec.data` is filled in for each part.
struct CodeJobObject {
  TextTemplate data;
  bool escapes = false;  // \G \R \E \xHH in the rendered data
  CodeObject code;
};

// One alternative per object kind ("text", "code"). The parser picks the kind from "kind"
// through a table in job_objects.cpp.
using ObjectBody = std::variant<TextObject, CodeJobObject>;

struct JobObject {
  std::string name;
  std::string kind = "text";
  std::string pen;
  ObjectBody body;
  MarkRequirement require;  // "require": what its mark must be to count as good
  // "overlaps": the objects (by name) whose ink this one's may touch on purpose; either side
  // naming the other is enough. Text objects only: a code's quiet zone is always checked.
  std::vector<std::string> overlaps;

  const TextObject* text() const { return std::get_if<TextObject>(&body); }
  const CodeJobObject* code() const { return std::get_if<CodeJobObject>(&body); }
  // The object's template, whatever its kind (the text, or the code's data).
  const TextTemplate& text_template() const { return text() ? text()->text : code()->data; }
};

// A data list the parts take their rows from, one per part ({col:NAME} fields; docs/store.md).
struct JobDataList {
  std::string file;       // as the job names it (the audit log keeps this)
  std::string path;       // resolved against the job file's folder
  char delimiter = ',';
};

struct JobFile {
  std::string source;          // the file name, for messages
  std::string job_name;        // "name", or the file's stem
  std::string device = "sim";
  HeadModel head = head_sl10();   // with the job's field size and spot diameter
  TimeZone time_zone = TimeZone::named("local");
  ShiftTable shifts;
  std::map<std::string, std::string> variables;  // defaults; --set overrides
  std::map<std::string, CounterSpec> counters;
  std::map<std::string, DateCodeTable> date_codes;  // {datecode:NAME} tables of the job
  std::optional<JobDataList> data;
  std::map<std::string, JobPen> pens;
  std::vector<JobObject> objects;

  // Objects i and j lie over each other on purpose (either names the other in "overlaps").
  bool overlap_allowed(std::size_t i, std::size_t j) const;

  // The counters the objects' templates use (what one part consumes).
  std::map<std::string, CounterSpec> used_counters() const;
  // Variables the templates use without a default: --set must give them.
  std::vector<std::string> required_variables() const;
};

// Throws InputError("<source>: <json path>: <problem>").
JobFile parse_job(std::string_view text, const std::string& source);
// Reads the file (and nothing else); `bytes` receives its content for the SHA-256.
JobFile read_job_file(const std::string& path, std::string* bytes = nullptr);

// Object kinds (job_objects.cpp): "text" → TextObject, "code" → CodeJobObject.
class JsonReader;
struct JobParseContext;
ObjectBody parse_object_body(const std::string& kind, JsonReader& object, const JobParseContext& ctx);
// An object's "require" (nothing asked when absent); a code grade needs a code object.
MarkRequirement parse_requirement(JsonReader& object, bool is_code);
std::vector<std::string> object_kind_names();

}  // namespace mark
