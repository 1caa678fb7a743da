#include "marker/production/job_file.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "base/error.hpp"
#include "base/input_file.hpp"
#include "driver/device_error.hpp"
#include "driver/lmc/lmc_spec.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/limits/device_settings.hpp"
#include "marker/limits/head_settings.hpp"
#include "marker/limits/pen_settings.hpp"
#include "marker/limits/production_settings.hpp"
#include "marker/production/job_parse_context.hpp"
#include "marker/production/json_reader.hpp"
#include "marker/vars/data_list.hpp"

namespace mark {
namespace {

// Duplicate keys and absurd nesting are errors too (nlohmann would keep the last silently).
struct StrictJson {
  std::vector<std::set<std::string>> keys;
  std::string duplicate;
};

nlohmann::json parse_strict(std::string_view text, const std::string& file) {
  StrictJson strict;
  const nlohmann::json::parser_callback_t cb = [&](int depth, nlohmann::json::parse_event_t event,
                                                   nlohmann::json& parsed) {
    using E = nlohmann::json::parse_event_t;
    if (depth > 32) throw InputError(file + ": nested more than 32 levels deep");
    if (event == E::object_start) strict.keys.emplace_back();
    if (event == E::object_end && !strict.keys.empty()) strict.keys.pop_back();
    if (event == E::key && !strict.keys.empty() && !strict.keys.back().insert(parsed.get<std::string>()).second &&
        strict.duplicate.empty())
      strict.duplicate = parsed.get<std::string>();
    return true;
  };
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text.begin(), text.end(), cb);
  } catch (const nlohmann::json::exception& e) {
    // A syntax error carries its byte; a number beyond a double (1e999) throws out_of_range,
    // which does not, so that one is named without a line and column.
    std::string where = file;
    if (const auto* pe = dynamic_cast<const nlohmann::json::parse_error*>(&e)) {
      std::size_t line = 1, col = 1;
      for (std::size_t i = 0; i + 1 < pe->byte && i < text.size(); ++i) {
        if (text[i] == '\n') ++line, col = 1;
        else ++col;
      }
      where += ":" + std::to_string(line) + ":" + std::to_string(col);
    }
    std::string what = e.what();
    // Drop nlohmann's "[json.exception.…] " tag and its "syntax error while parsing … at line 1: " lead.
    if (const std::size_t colon = what.rfind(": "); colon != std::string::npos) what = what.substr(colon + 2);
    else if (const std::size_t tag = what.find("] "); what.starts_with('[') && tag != std::string::npos)
      what = what.substr(tag + 2);
    throw InputError(where + ": not valid JSON: " + what);
  }
  if (!strict.duplicate.empty())
    throw InputError(file + ": key \"" + strict.duplicate + "\" appears twice in one object");
  return j;
}

HeadModel parse_head(JsonReader& top) {
  const nlohmann::json* h = top.raw(kHead.name.key);
  std::string model{kHead.value};
  std::optional<double> spot_um;
  if (h && h->is_string()) {
    model = h->get<std::string>();
  } else if (h) {
    JsonReader head = top.object(kHead.name.key);
    model = head.string("model").value_or(model);
    spot_um = head.number(kSpot);
    head.finish();
  }
  const auto found = find_head(model);
  if (!found) {
    std::string names;
    for (const std::string& n : head_names()) names += (names.empty() ? "" : ", ") + n;
    top.fail(h && h->is_object() ? "head.model" : "head", "\"" + model + "\" is not a head (" + names + ")");
  }
  HeadModel head = *found;
  if (spot_um) head.spot_diameter_um = *spot_um;
  return head;
}

CounterSpec parse_counter(JsonReader c, const std::string& name, const TimeZone& job_zone) {
  CounterSpec s;
  s.name = name;
  s.start = c.integer(kCounterStart).value_or(kCounterStart.fallback());
  s.step = c.integer(kCounterStep).value_or(kCounterStep.fallback());
  s.limit = c.integer(kCounterLimit);
  if (auto p = c.choice(kAtLimit)) s.at_limit = *parse_end_policy(*p);
  s.marks_per_serial = c.integer(kMarksPerSerial).value_or(kMarksPerSerial.fallback());
  s.width = static_cast<int>(c.integer(kCounterWidth).value_or(kCounterWidth.fallback()));
  if (auto p = c.choice(kPadding)) s.padding = *parse_padding(*p);
  const std::optional<std::string> alphabet = c.choice(kAlphabet);
  const std::optional<std::string> digits = c.string(kDigits);
  if (alphabet && digits)
    c.fail(kDigits.name.key, "give either \"alphabet\" or custom \"digits\", not both");
  if (alphabet) s.alphabet = *Alphabet::named(*alphabet);
  if (digits) s.alphabet = Alphabet::custom(*digits, c.file() + ": " + c.path_of(kDigits.name.key));
  if (auto r = c.choice(kReset)) s.reset = *parse_reset_rule(*r);
  s.time_zone = job_zone;
  if (auto z = c.string(kCounterTimeZone)) {
    try {
      s.time_zone = TimeZone::named(*z);
    } catch (const InputError& e) {
      c.fail(kCounterTimeZone.name.key, e.what());
    }
  }
  c.finish();
  try {
    s.validate(c.path());
  } catch (const InputError& e) {
    throw InputError(c.file() + ": " + e.what());
  }
  return s;
}

JobPen parse_pen(JsonReader p, const std::string& name, const HeadModel& head) {
  JobPen pen;
  pen.name = name;
  const std::string corner_name = p.choice(kCorner).value_or(std::string(kCorner.value));
  const CornerStrategy corner = parse_corner_strategy(corner_name);
  // A key this pen never reads is refused, as the command line refuses its option: a job file
  // has no look-ahead pen, so only the corner strategy decides.
  for (const SettingRef& s : kPenSettingList) {
    const std::string_view key = name_of(s).key;
    if (!key.empty() && p.has(key))
      if (const std::optional<std::string> why = pen_setting_unread(s, corner_name, false)) p.fail(key, *why);
  }
  // The speeds and the tick within the head's limits, in the command line's words.
  const double speed = p.number(kMarkSpeed, head_speed_range(kMarkSpeed, head)).value_or(kMarkSpeed.fallback());
  const double tick_us = p.number(kTick, head_tick_range(head)).value_or(kTick.fallback());
  Pen& m = pen.motion;
  m = pen_for_head(head, corner, speed, tick_us * 1e-6);
  m.jump_speed_mm_s = p.number(kJumpSpeed, head_speed_range(kJumpSpeed, head)).value_or(m.jump_speed_mm_s);
  if (corner == CornerStrategy::blanking) m.join_speed_mm_s = m.jump_speed_mm_s;
  // Each given value replaces the head's default, scaled from the key's unit.
  const auto set = [&](const Quantity& s, double& field, double scale) {
    if (auto v = p.number(s)) field = *v * scale;
  };
  set(kLaserOnDelay, m.laser_on_delay_s, 1e-6);
  set(kLaserOffDelay, m.laser_off_delay_s, 1e-6);
  set(kJumpDelay, m.jump_delay_s, 1e-6);
  set(kMarkDelay, m.mark_delay_s, 1e-6);
  set(kPolygonDelay, m.polygon_delay_s, 1e-6);
  set(kJumpSettle, m.jump_settle_mm, 1e-3);
  set(kBlankAngle, m.blank_angle_deg, 1);
  if (auto v = p.number(kRunIn)) m.run_in_mm = *v;
  set(kMinRunIn, m.min_run_in_mm, 1);
  set(kRunOut, m.run_out_mm, 1);
  set(kSettle, m.settle_mm, 1e-3);
  if (auto v = p.number(kJoinSpeed, head_speed_range(kJoinSpeed, head))) m.join_speed_mm_s = *v;
  pen.laser.power_pct = p.number_or_default(kPower);
  pen.laser.frequency_khz = p.number_or_default(kFrequency);
  pen.laser.pulse_width_ns = p.number_or_default(kPulseWidth);
  if (auto src = p.choice(kLaserSource)) pen.laser.source = *parse_laser_source(*src);
  try {
    check_laser_settings(pen.laser);  // what the pen's source cannot take (a CO2 pulse width)
  } catch (const InputError& e) {
    p.fail_here(e.what());
  }
  pen.passes = static_cast<int>(p.integer(kPasses).value_or(kPasses.fallback()));
  p.finish();
  return pen;
}

void check_name(JsonReader& r, std::string_view key, const std::string& name, const char* what) {
  if (name.empty()) r.fail(key, std::string("a ") + what + " needs a name");
  for (char c : name)
    if (c < 0x20 || c == '{' || c == '}' || c == ':')
      r.fail(key, std::string("a ") + what + " name cannot hold control characters, braces or colons");
}

// "sim", or a board as --device names it: a station's job says which device it marks on.
std::string parse_device(JsonReader& top) {
  const std::optional<std::string> device = top.string(kDevice);
  if (!device || *device == "sim") return "sim";
  try {
    if (lmc::parse_lmc_spec(*device, "")) return *device;
  } catch (const DeviceError& e) {
    top.fail(kDevice.name.key, e.what());
  }
  top.fail(kDevice.name.key, "'" + *device + "' is not a device (sim: the simulated scanner; lmc, "
                     "lmc:SERIAL, lmc-capture:FILE: a BJJCZ LMC board; lmc-emulated[:VARIANT]: the "
                     "emulated board)");
}

// A date-code table: {"unit": "month", "codes": ["A", "B", …]} (the unit's first value takes the
// first code) or {"unit": "year", "codes": {"2026": "T", …}}; every code non-empty.
DateCodeTable parse_date_code_table(JsonReader& t) {
  DateCodeTable table;
  const std::string units = date_unit_names();
  const std::optional<std::string> unit = t.string("unit");
  if (!unit || !parse_date_unit(*unit)) t.fail("unit", "expected one of " + units);
  table.unit = *parse_date_unit(*unit);
  const nlohmann::json* codes = t.raw("codes");
  const int first = first_value(table.unit), last = last_value(table.unit);
  const std::string range = table.unit == DateUnit::year ? std::string("1 to 9999")
                                                         : std::to_string(first) + " to " + std::to_string(last);
  const auto code_at = [&](const nlohmann::json& c, int value, const std::string& key) {
    if (!c.is_string() || c.get<std::string>().empty())
      t.fail("codes", "the code for " + std::string(to_string(table.unit)) + " " + key + " is not a non-empty string");
    table.codes[value] = c.get<std::string>();
  };
  if (codes && codes->is_array() && table.unit != DateUnit::year) {
    if (codes->empty() || static_cast<int>(codes->size()) > last - first + 1)
      t.fail("codes", "a list of 1 to " + std::to_string(last - first + 1) + " codes, for " +
                          std::string(to_string(table.unit)) + " " + range);
    for (std::size_t i = 0; i < codes->size(); ++i)
      code_at((*codes)[i], first + static_cast<int>(i), std::to_string(first + static_cast<int>(i)));
  } else if (codes && codes->is_object() && !codes->empty()) {
    for (const auto& [key, c] : codes->items()) {
      int value = 0;
      const auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), value);
      const bool in_range = table.unit == DateUnit::year ? value >= 1 && value <= 9999 : value >= first && value <= last;
      if (ec != std::errc{} || end != key.data() + key.size() || !in_range)
        t.fail("codes", "\"" + key + "\" is not a " + std::string(to_string(table.unit)) + " (" + range + ")");
      code_at(c, value, key);
    }
  } else {
    t.fail("codes", table.unit == DateUnit::year
                        ? "expected an object of year → code: {\"2026\": \"T\", …}"
                        : "expected a list of codes from " + std::to_string(first) + " on, or an object of " +
                              std::string(to_string(table.unit)) + " → code");
  }
  t.finish();
  return table;
}

// An object's "overlaps": a list of other objects' names, each once (checked against the job's
// objects by check_overlaps once all are read: a name may be a later object's).
std::vector<std::string> parse_overlaps(JsonReader& o, const std::string& self) {
  const std::string_view key = kObjectOverlaps.name.key;
  const nlohmann::json* list = o.raw(key);
  if (!list) return {};
  if (!list->is_array()) o.fail(key, "expected a list of object names: [\"frame\"]");
  std::vector<std::string> names;
  for (std::size_t k = 0; k < list->size(); ++k) {
    const nlohmann::json& n = (*list)[k];
    const std::string at = json_index(key, k);
    if (!n.is_string()) o.fail(at, "expected an object's name (a string)");
    const std::string name = n.get<std::string>();
    check_name(o, at, name, "object");  // the names' own rules: no control character reaches a message
    if (name == self) o.fail(at, "\"" + name + "\" is this object; name the objects it lies over");
    if (std::find(names.begin(), names.end(), name) != names.end()) o.fail(at, "\"" + name + "\" is named twice");
    names.push_back(name);
  }
  return names;
}

// Every "overlaps" name is another text object of the job: a code's quiet zone must stay bare.
void check_overlaps(const JobFile& job, const nlohmann::json& objects) {
  const std::string_view key = kObjectOverlaps.name.key;
  for (std::size_t i = 0; i < job.objects.size(); ++i) {
    const JobObject& obj = job.objects[i];
    const JsonReader o(objects[i], job.source, json_index("objects", i));
    for (std::size_t k = 0; k < obj.overlaps.size(); ++k) {
      const std::string& name = obj.overlaps[k];
      const auto other = std::find_if(job.objects.begin(), job.objects.end(),
                                      [&](const JobObject& x) { return x.name == name; });
      const std::string at = json_index(key, k);
      if (other == job.objects.end()) o.fail(at, "no object named \"" + name + "\"");
      if (obj.code() || other->code())
        o.fail(at, "\"" + (obj.code() ? obj.name : name) +
                       "\" is a code: its quiet zone must stay bare, so no object may lie over it");
    }
  }
}

}  // namespace

std::map<std::string, CounterSpec> JobFile::used_counters() const {
  std::map<std::string, CounterSpec> used;
  for (const JobObject& o : objects)
    for (const std::string& c : o.text_template().counters()) used.emplace(c, counters.at(c));
  return used;
}

bool JobFile::overlap_allowed(std::size_t i, std::size_t j) const {
  const auto names = [](const JobObject& o, const std::string& other) {
    return std::find(o.overlaps.begin(), o.overlaps.end(), other) != o.overlaps.end();
  };
  return names(objects[i], objects[j].name) || names(objects[j], objects[i].name);
}

std::vector<std::string> JobFile::required_variables() const {
  std::vector<std::string> names;
  for (const JobObject& o : objects)
    for (const std::string& v : o.text_template().variables())
      if (!variables.count(v) && std::find(names.begin(), names.end(), v) == names.end())
        names.push_back(v);
  return names;
}

JobFile parse_job(std::string_view text, const std::string& source) {
  const nlohmann::json j = parse_strict(text, source);
  JsonReader top(j, source, "");
  JobFile job;
  job.source = source;
  const std::optional<std::string> format = top.string("format");
  if (!format) top.fail("format", "missing: a job file starts with \"format\": \"" + std::string(kJobFormat) + "\"");
  if (*format != kJobFormat)
    top.fail("format", "\"" + *format + "\" is not a format this program reads (" + std::string(kJobFormat) + ")");
  job.job_name = top.string("name").value_or(std::filesystem::path(source).stem().string());
  job.device = parse_device(top);
  job.head = parse_head(top);
  job.head.field_mm = top.number(kField).value_or(job.head.field_mm);
  if (auto z = top.string(kTimeZone)) {
    try {
      job.time_zone = TimeZone::named(*z);
    } catch (const InputError& e) {
      top.fail(kTimeZone.name.key, e.what());
    }
  }
  if (const nlohmann::json* shifts = top.raw(kShifts.name.key)) {
    if (!shifts->is_array()) top.fail(kShifts.name.key, "expected a list of {\"code\": …, \"start\": \"HH:MM\"}");
    std::vector<Shift> list;
    for (std::size_t i = 0; i < shifts->size(); ++i) {
      JsonReader s((*shifts)[i], source, json_index("shifts", i));
      Shift sh;
      sh.code = s.string("code").value_or("");
      if (sh.code.empty()) s.fail("code", "a shift needs a code");
      const auto start = s.string("start");
      if (!start) s.fail("start", "a shift needs its start time \"HH:MM\"");
      sh.start_minute = parse_clock_time(*start, source + ": " + s.path_of("start"));
      s.finish();
      list.push_back(sh);
    }
    try {
      job.shifts = ShiftTable(std::move(list));
    } catch (const InputError& e) {
      top.fail("shifts", e.what());
    }
  }
  if (top.has(kVariables.name.key)) {
    JsonReader vars = top.object(kVariables.name.key);
    for (const auto& [k, v] : top.raw(kVariables.name.key)->items()) {
      const std::optional<std::string> value = vars.string(k);
      check_name(vars, k, k, "variable");
      job.variables[k] = *value;
    }
  }
  if (top.has("counters")) {
    JsonReader counters = top.object("counters");
    for (const auto& [k, v] : top.raw("counters")->items()) {
      check_name(counters, k, k, "counter");
      if (k == "date" || k == "var" || k == "shift" || k == "col" || k == "datecode" || k == "check")
        counters.fail(k, "\"" + k + "\" is a field name of its own; call the counter something else");
      job.counters.emplace(k, parse_counter(counters.object(k), k, job.time_zone));
    }
  }
  if (top.has("date_codes")) {
    JsonReader tables = top.object("date_codes");
    for (const auto& [k, v] : top.raw("date_codes")->items()) {
      check_name(tables, k, k, "date-code table");
      if (builtin_date_code_table(k)) tables.fail(k, "\"" + k + "\" is a built-in table; call yours something else");
      JsonReader t = tables.object(k);
      job.date_codes.emplace(k, parse_date_code_table(t));
    }
  }
  if (top.has("data")) {
    JsonReader d = top.object("data");
    JobDataList list;
    list.file = d.string("file").value_or("");
    if (list.file.empty()) d.fail("file", "a data list needs its CSV file");
    const std::filesystem::path file(list.file);
    list.path = file.is_absolute() ? list.file : (std::filesystem::path(source).parent_path() / file).string();
    if (auto delim = d.string("delimiter")) {
      const auto c = parse_delimiter(*delim);
      if (!c) d.fail("delimiter", "\"" + *delim + "\" is not a delimiter: \",\", \";\" or \"tab\"");
      list.delimiter = *c;
    }
    d.finish();
    job.data = list;
  }
  if (top.has("pens")) {
    JsonReader pens = top.object("pens");
    for (const auto& [k, v] : top.raw("pens")->items()) {
      check_name(pens, k, k, "pen");
      job.pens.emplace(k, parse_pen(pens.object(k), k, job.head));
    }
  }
  if (job.pens.empty()) top.fail("pens", "a job needs at least one pen");
  const nlohmann::json* objects = top.raw("objects");
  if (!objects || !objects->is_array() || objects->empty())
    top.fail("objects", "a job needs a list of at least one object to mark");
  const JobParseContext ctx{source, job.head.spot_diameter_um};
  std::set<std::string> names;
  for (std::size_t i = 0; i < objects->size(); ++i) {
    JsonReader o((*objects)[i], source, json_index("objects", i));
    JobObject obj;
    const std::string_view name_key = kObjectName.name.key, pen_key = kObjectPen.name.key;
    obj.name = o.string(kObjectName).value_or("");
    check_name(o, name_key, obj.name, "object");
    if (!names.insert(obj.name).second) o.fail(name_key, "another object is called \"" + obj.name + "\"");
    obj.kind = o.string("kind").value_or("text");
    const std::optional<std::string> pen = o.string(kObjectPen);
    if (pen) {
      if (!job.pens.count(*pen)) o.fail(pen_key, "no pen named \"" + *pen + "\"");
      obj.pen = *pen;
    } else if (job.pens.size() == 1) {
      obj.pen = job.pens.begin()->first;
    } else {
      o.fail(pen_key, "missing: the job has several pens, say which one draws this object");
    }
    obj.body = parse_object_body(obj.kind, o, ctx);
    obj.require = parse_requirement(o, obj.code() != nullptr);
    obj.overlaps = parse_overlaps(o, obj.name);
    o.finish();
    {
      const TextTemplate& t = obj.text_template();
      for (const std::string& c : t.counters())
        if (!job.counters.count(c))
          o.fail(kTemplate.name.key, "{" + c + "}: no counter named \"" + c + "\" in \"counters\"");
      for (const std::string& d : t.date_code_tables())
        if (!job.date_codes.count(d) && !builtin_date_code_table(d))
          o.fail(kTemplate.name.key, "{datecode:" + d + "}: no table named \"" + d +
                                         "\" in \"date_codes\" (built in: vin-year)");
      if (t.uses(FieldKind::shift) && job.shifts.empty())
        o.fail(kTemplate.name.key, "{shift} needs the job's \"shifts\" (codes and start times)");
      if (t.uses(FieldKind::column) && !job.data)
        o.fail(kTemplate.name.key, "{col:" + t.columns().front() + "} needs the job's data list (\"data\": {\"file\": …})");
    }
    job.objects.push_back(std::move(obj));
  }
  check_overlaps(job, *objects);
  for (const auto& [name, c] : job.counters)
    if (c.reset == ResetRule::shift && job.shifts.empty())
      top.fail("counters." + name + ".reset", "a reset at shift start needs the job's \"shifts\"");
  top.finish();
  return job;
}

JobFile read_job_file(const std::string& path, std::string* bytes) {
  const std::string text = read_input_file(path, "job file", 16u << 20);
  JobFile job = parse_job(text, path);
  if (bytes) *bytes = text;
  return job;
}

}  // namespace mark
