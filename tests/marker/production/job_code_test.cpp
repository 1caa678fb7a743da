// Codes and filled text in job files: a UDI code whose data carries the same serial as the text
// beside it, rendered from one allocation; a filled outline-font text; both read back field by
// field, compiled, and the code read back off the simulated mark with the part's serial; and
// the errors of the new keys naming file, JSON path and problem.
#include <gtest/gtest.h>

#include "base/error.hpp"
#include "marker/job/simulate_plan.hpp"
#include "marker/production/job_file.hpp"
#include "marker/production/part_texts.hpp"

namespace mark {
namespace {

constexpr const char* kJob = R"({
  "format": "marker-job/1",
  "head": {"model": "SL10", "spot_diameter_um": 40},
  "counters": {"serial": {"start": 41, "width": 6}},
  "pens": {"text": {"speed_mm_s": 800}, "code": {"speed_mm_s": 1000}},
  "objects": [
    {"name": "sn", "pen": "text", "template": "SN {serial}", "font": "DejaVuSans", "height_mm": 3,
     "x_mm": -10, "y_mm": 4,
     "fill": {"sets": [{"angle_deg": 0, "spacing_mm": 0.04}, {"angle_deg": 90}], "contour_passes": 1,
              "rule": "nonzero"}},
    {"name": "udi", "kind": "code", "pen": "code", "symbology": "gs1-datamatrix",
     "template": "(01)09506000134352(17)261231(10)LOT42(21){serial}", "module_mm": 0.25,
     "x_mm": 5, "y_mm": -3, "style": "square", "hatch": {"spacing_mm": 0.03, "direction": "unidirectional"}}
  ]
})";

std::string error_of(const std::string& text) {
  try {
    parse_job(text, "job.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

std::string with(const std::string& from, const std::string& to) {
  std::string s = kJob;
  const std::size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

TEST(JobCode, ReadsTheCodeAndTheFill) {
  const JobFile job = parse_job(kJob, "job.json");
  ASSERT_EQ(job.objects.size(), 2u);
  const TextObject* sn = job.objects[0].text();
  ASSERT_TRUE(sn && sn->fill);
  ASSERT_EQ(sn->fill->sets.size(), 2u);
  EXPECT_DOUBLE_EQ(sn->fill->sets[0].spacing_mm, 0.04);
  EXPECT_DOUBLE_EQ(sn->fill->sets[1].angle_deg, 90);
  EXPECT_DOUBLE_EQ(sn->fill->inset_mm, 0.02);  // the spot's radius
  EXPECT_EQ(sn->fill->contour_passes, 1);
  const CodeJobObject* udi = job.objects[1].code();
  ASSERT_TRUE(udi);
  EXPECT_EQ(udi->code.spec.symbology, Symbology::gs1_datamatrix);
  EXPECT_DOUBLE_EQ(udi->code.layout.module_mm, 0.25);
  EXPECT_EQ(udi->code.layout.fill.direction, HatchDirection::unidirectional);
  EXPECT_DOUBLE_EQ(udi->code.layout.fill.sets.front().spacing_mm, 0.03);
  // The code's template uses the counter: the part consumes it once for both objects.
  EXPECT_EQ(job.used_counters().size(), 1u);
}

TEST(JobCode, TextAndCodeCarryTheSameSerialAndTheCodeReadsBack) {
  const JobFile job = parse_job(kJob, "job.json");
  const std::vector<ObjectText> texts = render_objects(job, {}, SysTime{}, {{"serial", 42}});
  ASSERT_EQ(texts.size(), 2u);
  EXPECT_EQ(texts[0].text, "SN 000042");
  EXPECT_EQ(texts[1].text, "(01)09506000134352(17)261231(10)LOT42(21)000042");
  const JobFonts fonts(job);
  const JobSpec text_spec = object_spec(job, job.objects[0], texts[0].text, fonts);
  ASSERT_TRUE(text_spec.fill);
  const CompiledJob text = compile_job(text_spec);
  EXPECT_GT(text.plan.strokes, 300u);  // hatch lines and contour loops, not 9 outlines
  const JobSpec code_spec = object_spec(job, job.objects[1], texts[1].text, fonts);
  const SimulatedJob code = simulate_job(code_spec);
  ASSERT_EQ(code.codes.size(), 1u);
  EXPECT_TRUE(code.codes[0].data_match);
  EXPECT_EQ(code.codes[0].decoded_data, "01095060001343521726123110LOT42\x1d" "21000042");
}

TEST(JobCode, MalformedCodesAndFillsGiveOneLineErrors) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {with("\"symbology\": \"gs1-datamatrix\",", ""),
       "job.json: objects[1].symbology: a code object needs its symbology (datamatrix, …)"},
      {with("\"gs1-datamatrix\"", "\"pdf417\""),
       "job.json: objects[1].symbology: \"pdf417\" is not one of datamatrix, gs1-datamatrix, qr, code128, gs1-128"},
      {with("\"module_mm\": 0.25,", "\"module_mm\": 0.25, \"size_mm\": 4,"),
       "job.json: objects[1].module_mm: give size_mm or module_mm, not both"},
      {with("\"module_mm\": 0.25,", "\"matrix_size\": \"11x11x\","),
       "job.json: objects[1].matrix_size: Data Matrix size '11x11x': expected ROWSxCOLUMNS such as 16x16 or 16x48"},
      {with("\"style\": \"square\"", "\"style\": \"star\""),
       "job.json: objects[1].style: \"star\" is not one of square, dot, line"},
      {with("\"spacing_mm\": 0.03", "\"spacing_mm\": 0"),
       "job.json: objects[1].hatch.spacing_mm: 0 is outside the range 0.001 to 10 mm"},
      {with("\"contour_passes\": 1", "\"contour_passes\": 1, \"loops\": 2"),
       "job.json: objects[0].fill.loops: unknown key"},
      {with("{\"angle_deg\": 90}", "{\"angle_deg\": 90, \"spacing\": 1}"),
       "job.json: objects[0].fill.sets[1].spacing: unknown key"},
      {with("(21){serial}", "(21){lot}"),
       "job.json: objects[1].template: {lot}: no counter named \"lot\" in \"counters\""},
  };
  for (const auto& [text, expected] : cases) EXPECT_EQ(error_of(text).substr(0, expected.size()), expected);
}

}  // namespace
}  // namespace mark
