// `marker code SYMBOLOGY DATA [--size MM | --module MM] [--style square|dot|line] [--x --y]
//  [--json] [--preview FILE] [--dose-png FILE] …`
// One code marked alone on the simulated scanner — through the same job runner as `mark`, in
// device time — then photographed by the simulated reader's camera, read by real decoders
// (ZXing, libdmtx, ZBar) and graded after ISO/IEC TR 29158. Exit 0 when it reads back as the
// data (and meets --require-grade), 2 when not.
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "driver/sim/grey_png.hpp"
#include "marker/cli/code_options.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/hatch_options.hpp"
#include "marker/cli/head_options.hpp"
#include "marker/cli/output_options.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/pen_options.hpp"
#include "marker/cli/unread_options.hpp"
#include "marker/codes/code_data.hpp"
#include "marker/codes/code_json.hpp"
#include "marker/job/job.hpp"
#include "marker/job/sim_evaluator.hpp"
#include "marker/limits/code_settings.hpp"
#include "marker/limits/head_settings.hpp"
#include "marker/limits/production_settings.hpp"
#include "marker/output/output_file.hpp"
#include "marker/preview/mark_preview.hpp"

namespace mark::cli {
namespace {

struct CodeCommandArgs {
  std::string symbology;
  std::string data;
  CodeArgs code;
  HatchArgs hatch;
  HeadArgs head;
  double field_mm = *kField.value;
  PenArgs pen;
  VerifyArgs verify;
  std::string preview;
  std::string dose_png;
  std::string camera_png;
  std::string require_grade;
  bool json = false;
};

JobSpec make_spec(const CodeCommandArgs& a) {
  JobSpec spec;
  spec.verify = to_verify_options(a.verify);
  // Marks end a beam radius inside their modules unless the hatch inset says otherwise.
  const FillOptions hatch = to_fill_options(a.hatch, a.verify.beam_diameter_mm / 2);
  spec.codes.push_back(to_code_object(a.symbology, a.data, a.code, hatch, ""));
  spec.head = simulated_head(a.head);
  spec.head.field_mm = a.field_mm;
  spec.pen = make_pen(a.pen, spec.head);
  return spec;
}

void print_summary(const JobSpec& spec, const JobResult& r) {
  const PlacedCode& c = r.job.codes.front();
  const CodeVerification& v = r.codes.front();
  std::printf("%s %dx%d, module %.3f mm (%.2f x %.2f mm, quiet zone %d modules), %s modules%s: %zu marks, %.1f mm\n",
              std::string(to_string(c.matrix.symbology)).c_str(), c.matrix.rows, c.matrix.cols, c.module_mm,
              c.width_mm, c.height_mm, c.quiet_modules, std::string(to_string(c.layout.style)).c_str(),
              c.layout.invert ? ", inverted" : "", c.stats.hatch_lines, c.stats.hatch_length_mm);
  std::printf("marked on %s, %s corners, %.0f mm/s: %.4f s (device), %zu strokes, jumps %.1f mm\n",
              spec.head.name.c_str(), std::string(to_string(spec.pen.corner)).c_str(), spec.pen.mark_speed_mm_s,
              r.mark_time_s, r.strokes, r.jump_length_mm);
  std::printf("readers (%s decides):", v.decided_by.c_str());
  for (const ReaderOutcome& o : v.readers)
    std::printf(" %s %s;", o.reader.c_str(),
                !o.supported ? "n/a" : o.data_match ? "reads" : o.decoded ? "MISREADS" : "no read");
  std::printf(" %s", v.data_match ? "PASS" : "FAIL");
  if (v.decoded) std::printf(", '%s'", printable_bytes(v.decoded_data).c_str());
  std::printf("\n");
  if (v.module_x_um) {
    std::printf("module %.1f", *v.module_x_um);
    if (v.module_y_um) std::printf(" x %.1f", *v.module_y_um);
    std::printf(" µm (%s), ", v.reader.c_str());
  }
  if (v.fill_ratio)
    std::printf("fill %.0f %% (least %.0f %%), spill %.1f %%, ", 100 * *v.fill_ratio, 100 * *v.fill_ratio_min,
                100 * *v.spill_ratio);
  std::printf("%zu modules wrong, camera %.0f µm/px\n", v.modules_wrong, v.camera_px_um);
  if (v.grade) {
    const IsoGrade& g = *v.grade;
    std::printf("ISO/IEC TR 29158 grade %c: decode %c, cell contrast %c (%.0f %%), cell modulation %c, "
                "fixed pattern %c, axial non-uniformity %c (%.1f %%), grid non-uniformity %c (%.2f), "
                "unused error correction %c (%.0f %%)\n",
                grade_letter(g.overall), grade_letter(g.decode), grade_letter(g.cell_contrast_grade),
                100 * g.cell_contrast, grade_letter(g.cell_modulation_grade), grade_letter(g.fixed_pattern_grade),
                grade_letter(g.axial_nonuniformity_grade), 100 * g.axial_nonuniformity,
                grade_letter(g.grid_nonuniformity_grade), g.grid_nonuniformity,
                grade_letter(g.unused_error_correction_grade), 100 * g.unused_error_correction);
  }
}

int run_code(const CodeCommandArgs& a) {
  const JobSpec spec = make_spec(a);
  check_standard_output({{"--preview", &a.preview}, {"--dose-png", &a.dose_png}}, a.json);
  if (!a.preview.empty()) check_output_path("--preview", a.preview, {".svg", ".png"});
  if (!a.dose_png.empty()) check_output_path("--dose-png", a.dose_png, {".png"});
  if (!a.camera_png.empty()) check_output_path("--camera-png", a.camera_png, {".png"});
  const int min_grade = a.require_grade.empty() ? 0 : parse_required_grade(a.require_grade, "--require-grade");
  check_reader_choice(spec.verify.reading.reader, place_encoded(spec.codes.front()), "--reader");
  JobOptions options;
  options.virtual_time = true;  // one code: nothing to learn from waiting for the clock
  options.realtime = false;
  SimScanner scanner(simulator_options(spec));
  const JobResult r = run_job_simulated(spec, options, scanner);
  if (r.outcome != JobOutcome::done)
    throw InputError("the code's mark did not finish (" + std::string(to_string(r.outcome)) + ")");
  const PlacedCode& code = r.job.codes.front();
  nlohmann::json j = code_to_json(code, spec.codes.front().spec, r.codes.front());
  j["mark_time_s"] = r.mark_time_s;
  j["jump_length_mm"] = r.jump_length_mm;
  j["strokes"] = r.strokes;
  j["head"] = spec.head.name;
  j["corner"] = std::string(to_string(spec.pen.corner));
  j["speed_mm_s"] = spec.pen.mark_speed_mm_s;
  if (!a.preview.empty())
    write_mark_preview(r.job.plan, scanner.picture_dose(), a.preview);  // written whole
  if (!a.dose_png.empty()) {
    const CameraSettings& cam = spec.verify.camera;
    const GreyImage picture = part_picture(scanner.picture_dose(), code_window(code, spec.verify.response),
                                           spec.verify.response, code.layout.invert ? dark_part_look(cam.look) : cam.look);
    write_file_whole(a.dose_png, encode_grey_png(picture));
    j["dose_px_um"] = 1e6 / pixels_per_metre(picture.pixel_mm);
  }
  if (!a.camera_png.empty()) {
    const GreyImage picture = code_picture(code, scanner.picture_dose(), spec.verify).picture;
    write_file_whole(a.camera_png, encode_grey_png(picture));
  }
  if (a.json) {
    std::cout << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  } else {
    print_summary(spec, r);
    if (!a.dose_png.empty()) std::printf("wrote %s\n", a.dose_png.c_str());
  }
  const CodeVerification& v = r.codes.front();
  if (min_grade > 0)
    if (const auto why = grade_shortfall(v, min_grade)) {
      std::fprintf(stderr, "marker: code below --require-grade %s: %s\n", a.require_grade.c_str(), why->c_str());
      return 2;
    }
  return v.data_match ? 0 : 2;
}

}  // namespace

Command make_code_command() {
  auto a = std::make_shared<CodeCommandArgs>();
  auto sub_app = std::make_shared<CLI::App*>();
  return Command(
      [a, sub_app](CLI::App& app) {
        auto* sub = app.add_subcommand("code", "mark one 2-D code or barcode on the simulated scanner and read it back");
        sub->add_option("symbology", a->symbology, "datamatrix, gs1-datamatrix, qr, code128, gs1-128")->required();
        sub->add_option("data", a->data, "data to encode (GS1: (01)09506000134352(17)261231(10)LOT42(21)SN1)")->required();
        add_code_options(*sub, a->code, "");
        add_hatch_options(*sub, a->hatch);
        add_head_options(*sub, a->head, false);
        add_setting(*sub, kField, a->field_mm);
        add_pen_options(*sub, a->pen);
        add_verify_options(*sub, a->verify);
        sub->add_option("--preview", a->preview, "write the planned path over the dose (.png or .svg)");
        sub->add_option("--dose-png", a->dose_png, "write the part itself at the dose raster's pixel (PNG, pixel size in pHYs)");
        sub->add_option("--camera-png", a->camera_png,
                        "write the code reader's camera picture (PNG, pixel size in pHYs)");
        add_setting(*sub, kRequireGrade, a->require_grade);
        sub->add_flag("--json", a->json, "print one JSON object with the code's figures");
        *sub_app = sub;
        return sub;
      },
      [a, sub_app] {
        // Options nothing reads are refused (unread_options.hpp) before anything is marked.
        refuse_unread_pen_options(**sub_app, a->pen);
        const SettingRef dot[] = {&kDotShape, &kDotSize};
        refuse_unread(**sub_app, dot, a->code.style == "dot", "only dot-style modules read it (give --style dot)");
        return run_code(*a);
      });
}

}  // namespace mark::cli
