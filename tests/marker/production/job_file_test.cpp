// Job files: a full job read back field by field, and every malformed file we could think of
// giving its one-line error naming the file, the JSON path and the problem.
#include <gtest/gtest.h>

#include "base/error.hpp"
#include "marker/production/job_file.hpp"

namespace mark {
namespace {

constexpr const char* kFileJob = R"({
  "format": "marker-job/1",
  "name": "bracket",
  "head": {"model": "SL14", "spot_diameter_um": 50},
  "field_mm": 100,
  "time_zone": "Europe/Berlin",
  "shifts": [{"code": "A", "start": "06:00"}, {"code": "B", "start": "14:00"}, {"code": "C", "start": "22:00"}],
  "variables": {"lot": "A00"},
  "counters": {
    "serial": {"start": 1, "step": 1, "width": 6, "limit": 999999, "at_limit": "wrap",
               "reset": "midnight"},
    "vin": {"start": 9223372036854775000, "step": -7, "alphabet": "base33", "marks_per_serial": 2,
            "padding": "blank", "time_zone": "UTC"}
  },
  "pens": {
    "fine": {"speed_mm_s": 800, "corner": "delays", "power_pct": 40, "frequency_khz": 60,
             "pulse_width_ns": 200, "source": "mopa", "passes": 2, "polygon_delay_us": 55},
    "deep": {"speed_mm_s": 300, "power_pct": 100, "frequency_khz": 20, "run_out_mm": 0.2}
  },
  "objects": [
    {"name": "sn", "pen": "fine", "template": "SN {serial} {shift}", "height_mm": 3,
     "align": "center", "x_mm": 1.5, "y_mm": -2, "italic_deg": 10},
    {"name": "lot", "kind": "text", "pen": "deep", "template": "LOT {var:lot} {vin:8}",
     "font": "builtin", "circle": {"cx_mm": 0, "cy_mm": 0, "radius_mm": 20, "inside": true},
     "order": "shortest", "mirror": true}
  ]
})";

std::string job_error_of(const std::string& text) {
  try {
    parse_job(text, "job.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

// The full job with one substring replaced.
std::string job_with(const std::string& from, const std::string& to) {
  std::string s = kFileJob;
  const std::size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

TEST(JobFile, ReadsEveryField) {
  const JobFile job = parse_job(kFileJob, "job.json");
  EXPECT_EQ(job.job_name, "bracket");
  EXPECT_EQ(job.device, "sim");  // the default
  for (const char* board : {"lmc", "lmc:1234ABCD", "lmc-capture:bracket.lmc", "lmc-emulated", "lmc-emulated:slowest", "sim"})
    EXPECT_EQ(parse_job(job_with("\"field_mm\": 100", std::string("\"field_mm\": 100, \"device\": \"") + board + "\""), "job.json").device, board);
  EXPECT_EQ(job.head.name, "SL14");
  EXPECT_DOUBLE_EQ(job.head.field_mm, 100);
  EXPECT_DOUBLE_EQ(job.head.spot_diameter_um, 50);
  EXPECT_EQ(job.time_zone.name(), "Europe/Berlin");
  ASSERT_EQ(job.shifts.shifts().size(), 3u);
  EXPECT_EQ(job.variables.at("lot"), "A00");
  const CounterSpec& serial = job.counters.at("serial");
  EXPECT_EQ(serial.width, 6);
  EXPECT_EQ(serial.limit, 999999);
  EXPECT_EQ(serial.at_limit, EndPolicy::wrap);
  EXPECT_EQ(serial.reset, ResetRule::midnight);
  EXPECT_EQ(serial.time_zone.name(), "Europe/Berlin");  // the job's zone by default
  const CounterSpec& vin = job.counters.at("vin");
  EXPECT_EQ(vin.start, 9223372036854775000);
  EXPECT_EQ(vin.step, -7);
  EXPECT_EQ(vin.alphabet.name(), "base33");
  EXPECT_EQ(vin.marks_per_serial, 2);
  EXPECT_EQ(vin.padding, Padding::blank);
  EXPECT_EQ(vin.time_zone.name(), "UTC");
  const JobPen& fine = job.pens.at("fine");
  EXPECT_EQ(fine.motion.corner, CornerStrategy::delays);
  EXPECT_DOUBLE_EQ(fine.motion.mark_speed_mm_s, 800);
  EXPECT_DOUBLE_EQ(fine.motion.polygon_delay_s, 55e-6);
  EXPECT_DOUBLE_EQ(fine.motion.laser_on_delay_s, 0.6 * 0.21e-3);  // SL14's τ by the RTC rule
  EXPECT_DOUBLE_EQ(fine.laser.power_pct, 40);
  EXPECT_DOUBLE_EQ(fine.laser.frequency_khz, 60);
  EXPECT_DOUBLE_EQ(fine.laser.pulse_width_ns, 200);
  EXPECT_EQ(fine.laser.source, LaserSource::mopa);
  EXPECT_EQ(job.pens.at("deep").laser.source, LaserSource::fiber);  // the default
  EXPECT_EQ(fine.passes, 2);
  EXPECT_DOUBLE_EQ(job.pens.at("deep").motion.run_out_mm, 0.2);
  ASSERT_EQ(job.objects.size(), 2u);
  const TextObject& sn = *job.objects[0].text();
  EXPECT_EQ(job.objects[0].pen, "fine");
  EXPECT_EQ(sn.text.source(), "SN {serial} {shift}");
  EXPECT_DOUBLE_EQ(sn.layout.height_mm, 3);
  EXPECT_EQ(sn.layout.align, Align::center);
  EXPECT_DOUBLE_EQ(sn.layout.base.x(), 1.5);
  EXPECT_DOUBLE_EQ(sn.layout.italic_deg, 10);
  const TextObject& lot = *job.objects[1].text();
  ASSERT_TRUE(lot.layout.circle);
  EXPECT_DOUBLE_EQ(lot.layout.circle->radius_mm, 20);
  EXPECT_TRUE(lot.layout.circle->inside);
  EXPECT_TRUE(lot.layout.mirror);
  EXPECT_EQ(lot.order, StrokeOrder::shortest);
  EXPECT_EQ(job.used_counters().size(), 2u);
  EXPECT_TRUE(job.required_variables().empty());
}

TEST(JobFile, MalformedFilesGiveOneLineErrors) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{", "job.json:1:2: not valid JSON: syntax error while parsing object key - unexpected end of input; expected string literal"},
      {"[]", "job.json: the job: expected an object {…}, found a list"},
      {"{\"a\": 91e308}", "job.json: not valid JSON: number overflow parsing '91e308'"},
      {"{}", "job.json: format: missing: a job file starts with \"format\": \"marker-job/1\""},
      {job_with("marker-job/1", "marker-job/2"), "job.json: format: \"marker-job/2\" is not a format this program reads (marker-job/1)"},
      {job_with("\"pen\": \"deep\"", "\"pen\": \"deeper\""), "job.json: objects[1].pen: no pen named \"deeper\""},
      {job_with("\"speed_mm_s\": 800", "\"speed_mm_sec\": 800"), "job.json: pens.fine.speed_mm_sec: unknown key (did you mean \"speed_mm_s\"?)"},
      {job_with("\"name\": \"bracket\"", "\"nmae\": \"bracket\""), "job.json: nmae: unknown key (did you mean \"name\"?)"},
      {job_with("\"power_pct\": 40", "\"power_pct\": 140"), "job.json: pens.fine.power_pct: 140 is outside the range 0 to 100 %"},
      {job_with("\"power_pct\": 40", "\"power_pct\": \"40\""), "job.json: pens.fine.power_pct: expected a number, found a string"},
      {job_with("\"frequency_khz\": 60", "\"frequency_khz\": 0"), "job.json: pens.fine.frequency_khz: 0 is outside the range 1 to 4000 kHz"},
      {job_with("\"passes\": 2", "\"passes\": 1.5"), "job.json: pens.fine.passes: expected a whole number, found a fraction"},
      {job_with("\"speed_mm_s\": 800", "\"speed_mm_s\": 1e9"), "job.json: pens.fine.speed_mm_s: 1e+09 is outside the range 0.001 to 16000 mm/s (head SL14's positioning limit)"},
      {job_with("\"corner\": \"delays\"", "\"corner\": \"round\""), "job.json: pens.fine.corner: \"round\" is not one of blanking, delays, none"},
      {job_with("\"SL14\"", "\"SL99\""), "job.json: head.model: \"SL99\" is not a head (SL10, SL14, cheap, SA14)"},
      {job_with("\"step\": -7", "\"step\": 0"), "job.json: counters.vin.step: a counter's step cannot be 0"},
      {job_with("\"limit\": 999999", "\"limit\": 9999999"), "job.json: counters.serial.width: 9999999 needs 7 decimal digits, the width is 6 (lower the limit or widen the field)"},
      {job_with("\"start\": 9223372036854775000", "\"start\": 9223372036854775808"), "job.json: counters.vin.start: 9223372036854775808 does not fit in 64 bits (at most 9223372036854775807)"},
      {job_with("\"alphabet\": \"base33\"", "\"alphabet\": \"base32\""), "job.json: counters.vin.alphabet: \"base32\" is not one of decimal, hex, base36, base33"},
      {job_with("\"alphabet\": \"base33\"", "\"digits\": \"AA\""), "job.json: counters.vin.digits: 'A' appears twice"},
      {job_with("\"reset\": \"midnight\"", "\"reset\": \"weekly\""), "job.json: counters.serial.reset: \"weekly\" is not one of never, midnight, shift"},
      {job_with("\"time_zone\": \"UTC\"", "\"time_zone\": \"Mars\""), "job.json: counters.vin.time_zone: time zone 'Mars' is not known (use local, UTC or a name like Europe/Berlin from the system's tz database)"},
      {job_with("{serial} {shift}", "{serail}"), "job.json: objects[0].template: {serail}: no counter named \"serail\" in \"counters\""},
      {job_with("{serial} {shift}", "{serial"), "job.json: objects[0].template: 'SN {serial' at character 4: '{' without a closing '}'"},
      {job_with("\"22:00\"", "\"24:00\""), "job.json: shifts[2].start: '24:00' is not a time of day (00:00 to 23:59)"},
      {job_with("\"22:00\"", "\"14:00\""), "job.json: shifts: shifts 'B' and 'C' both start at 14:00"},
      {job_with("\"kind\": \"text\"", "\"kind\": \"hologram\""), "job.json: objects[1].kind: \"hologram\" is not an object kind (text, code)"},
      {job_with("\"name\": \"lot\"", "\"name\": \"sn\""), "job.json: objects[1].name: another object is called \"sn\""},
      {job_with("\"radius_mm\": 20", "\"radius_mm\": -20"), "job.json: objects[1].circle.radius_mm: -20 is outside the range above 0, up to 10000 mm"},
      {job_with("\"height_mm\": 3", "\"height_mm\": 3, \"height_mm\": 4"), "job.json: key \"height_mm\" appears twice in one object"},
      {job_with("\"x_mm\": 1.5", "\"x_mm\": null"), "job.json: objects[0].x_mm: expected a number, found null"},
      {job_with("\"mirror\": true", "\"mirror\": 1"), "job.json: objects[1].mirror: expected true or false, found a number"},
      {job_with("\"template\": \"SN {serial} {shift}\", ", ""), "job.json: objects[0].template: a text object needs a template (the text to mark, fields in braces)"},
      {job_with("\"objects\": [", "\"objects\": [], \"x\": ["), "job.json: objects: a job needs a list of at least one object to mark"},
      {job_with("\"pen\": \"fine\", ", ""), "job.json: objects[0].pen: missing: the job has several pens, say which one draws this object"},
      {job_with("\"field_mm\": 100", "\"field_mm\": -1"), "job.json: field_mm: -1 is outside the range 1 to 10000 mm"},
      {job_with("\"variables\": {\"lot\": \"A00\"}", "\"variables\": {\"lot\": 7}"), "job.json: variables.lot: expected a string, found a number"},
      {job_with("\"counters\": {", "\"counters\": {\"date\": {},"), "job.json: counters.date: \"date\" is a field name of its own; call the counter something else"},
      {job_with("\"field_mm\": 100", "\"field_mm\": 100, \"device\": \"usb0\""), "job.json: device: 'usb0' is not a device (sim: the simulated scanner; lmc, lmc:SERIAL, lmc-capture:FILE: a BJJCZ LMC board; lmc-emulated[:VARIANT]: the emulated board)"},
      {job_with("\"field_mm\": 100", "\"field_mm\": 100, \"device\": \"lmc:xyz\""), "job.json: device: 'lmc:xyz': a board serial is 1 to 8 hex digits (use lmc, lmc:SERIAL with the serial `marker devices` lists, lmc-capture:FILE, or lmc-emulated[:VARIANT])"},
      {job_with("\"field_mm\": 100", "\"field_mm\": 100, \"device\": \"lmc-emulated:fast\""), "job.json: device: 'lmc-emulated:fast': no emulated board variant 'fast' (known: reference, exact_ticks, word_ticks, jump_waits, polygon_10us, shallow_buffer, deep_buffer, foreign_settings, slowest) (use lmc, lmc:SERIAL with the serial `marker devices` lists, lmc-capture:FILE, or lmc-emulated[:VARIANT])"},
      {job_with("\"source\": \"mopa\"", "\"source\": \"co2\""), "job.json: pens.fine: pulse width 200 ns: a co2 source (CO2 (continuous wave, PWM power)) has no settable pulse width (only mopa: 2 .. 500 ns; 0 for the source's own)"},
      {job_with("\"source\": \"mopa\"", "\"source\": \"laser\""), "job.json: pens.fine.source: \"laser\" is not one of fiber, mopa, co2, uv"},
      {job_with("\"frequency_khz\": 20", "\"frequency_khz\": 500"), "job.json: pens.deep: frequency 500 kHz is outside what a fiber source runs (Q-switched fiber: 1 .. 200 kHz)"},
      {job_with("\"field_mm\": 100", "\"field_mm\": 100, \"device\": 7"), "job.json: device: expected a string, found a number"},
  };
  for (const auto& [text, expected] : cases) EXPECT_EQ(job_error_of(text), expected);
}

TEST(JobFile, RequiredVariablesAndSinglePenDefault) {
  const JobFile job = parse_job(R"({"format": "marker-job/1",
    "pens": {"p": {}}, "objects": [{"name": "a", "template": "LOT {var:lot}"}]})", "mini.json");
  EXPECT_EQ(job.objects[0].pen, "p");
  EXPECT_EQ(job.required_variables(), (std::vector<std::string>{"lot"}));
  EXPECT_EQ(job.job_name, "mini");
  EXPECT_EQ(job.head.name, "SL10");
}

TEST(JobFile, ShiftResetNeedsShifts) {
  EXPECT_EQ(job_error_of(R"({"format": "marker-job/1", "counters": {"n": {"reset": "shift"}},
    "pens": {"p": {}}, "objects": [{"name": "a", "template": "{n}"}]})"),
            "job.json: counters.n.reset: a reset at shift start needs the job's \"shifts\"");
}

// Every file the user names is read bounded (base/input_file.hpp): a missing file, a directory
// and an endless device are each refused in one line, the endless one after the bound (16 MiB)
// rather than when memory runs out.
TEST(JobFile, AMissingFileADirectoryOrAnEndlessDeviceIsRefusedNamingIt) {
  const auto refusal = [](const std::string& path) {
    try {
      read_job_file(path);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal("/nonexistent/job.json"), "/nonexistent/job.json: cannot read the job file: No such file or directory");
  EXPECT_EQ(refusal("/tmp"), "/tmp: cannot read the job file: it is a directory");
  EXPECT_EQ(refusal("/dev/zero"), "/dev/zero: cannot read the job file: longer than 16 MiB, the most a job file may be");
}

}  // namespace
}  // namespace mark
