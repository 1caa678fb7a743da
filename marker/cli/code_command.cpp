// `marker code SYMBOLOGY DATA [--size MM | --module MM] [--style square|dot|line] [--x --y]
//  [--json] [--preview FILE] [--dose-png FILE] …`
// One code marked alone on the simulated scanner, then read back off the simulated part by a
// real decoder (libdmtx, ZBar), with grade-like figures.
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "driver/grey_png.hpp"
#include "fonts/error.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/hatch_options.hpp"
#include "marker/cli/pen_options.hpp"
#include "marker/codes/code_data.hpp"
#include "marker/codes/code_job.hpp"
#include "marker/codes/code_json.hpp"
#include "marker/common/range_check.hpp"
#include "marker/preview/mark_preview.hpp"

namespace mark::cli {
namespace {

struct CodeArgs {
  std::string symbology;
  std::string data;
  bool escapes = false;
  std::optional<double> size_mm;
  std::optional<double> module_mm;
  std::optional<double> bar_height_mm;
  std::string matrix_size;
  std::string shape = "square";
  std::string qr_ecc = "M";
  int qr_version = 0;
  std::string style = "square";
  std::string dot = "spiral";
  double dot_size = 1.0;
  bool invert = false;
  double x_mm = 0, y_mm = 0, angle_deg = 0;
  HatchArgs hatch;
  PenArgs pen;
  double beam_diameter_mm = 0.05;
  double line_width_mm = 0.05;
  double line_speed_mm_s = 1000;
  double pixels_per_module = 7;
  double aperture = 0.5;
  std::string preview;
  std::string dose_png;
  bool json = false;
};

CodeJob make_job(const CodeArgs& a) {
  CodeJob job;
  job.spec.symbology = parse_symbology(a.symbology);
  job.spec.data = a.escapes ? unescape_code_data(a.data) : a.data;
  if (!a.matrix_size.empty()) parse_matrix_size(a.matrix_size, job.spec.matrix_rows, job.spec.matrix_cols);
  job.spec.shape = parse_matrix_shape(a.shape);
  if (a.qr_ecc.size() != 1) throw InputError("--qr-ecc '" + a.qr_ecc + "' is not one of L, M, Q, H");
  job.spec.qr_ecc = a.qr_ecc.front();
  job.spec.qr_version = a.qr_version;

  require_in_range("--beam-diameter", a.beam_diameter_mm, 0.001, 5, "mm");
  require_in_range("--line-width", a.line_width_mm, 0.001, 3 * a.beam_diameter_mm, "mm");
  require_in_range("--line-speed", a.line_speed_mm_s, 1, 100000, "mm/s");
  require_in_range("--pixels-per-module", a.pixels_per_module, 3, 20);
  require_in_range("--aperture", a.aperture, 0, 1.5, "modules");
  job.verify.response = {a.beam_diameter_mm, a.line_speed_mm_s, a.line_width_mm};
  job.verify.pixels_per_module = a.pixels_per_module;
  job.verify.aperture_modules = a.aperture;

  CodeLayout& l = job.layout;
  l.center = Point(a.x_mm, a.y_mm);
  l.angle_deg = a.angle_deg;
  // Given means given: 0 is not "automatic" on the command line.
  if (a.size_mm) require_in_range("--size", *a.size_mm, 0.05, 500, "mm");
  if (a.module_mm) require_in_range("--module", *a.module_mm, 0.01, 20, "mm");
  if (a.bar_height_mm) require_in_range("--bar-height", *a.bar_height_mm, 0.1, 500, "mm");
  if (a.size_mm && a.module_mm) throw InputError("give --size or --module, not both");
  l.size_mm = a.size_mm.value_or(0);
  l.module_mm = a.module_mm.value_or(0);
  l.bar_height_mm = a.bar_height_mm.value_or(0);
  l.style = parse_module_style(a.style);
  l.dot = parse_dot_shape(a.dot);
  l.dot_share = a.dot_size;
  l.invert = a.invert;
  // Marks end a beam radius inside their modules unless the hatch inset says otherwise.
  l.fill = to_fill_options(a.hatch, a.beam_diameter_mm / 2);

  const HeadAndPen hp = make_head_and_pen(a.pen);
  job.head = hp.head;
  job.pen = hp.pen;
  return job;
}

void print_summary(const CodeJob& job, const CodeJobResult& r, const std::string& dose_png) {
  const PlacedCode& c = r.code;
  const CodeVerification& v = r.verification;
  std::printf("%s %dx%d, module %.3f mm (%.2f x %.2f mm, quiet zone %d modules), %s modules%s: %zu lines, %.1f mm\n",
              std::string(to_string(job.spec.symbology)).c_str(), c.matrix.rows, c.matrix.cols, c.module_mm,
              c.width_mm, c.height_mm, c.quiet_modules, std::string(to_string(c.layout.style)).c_str(),
              c.layout.invert ? ", inverted" : "", c.stats.hatch_lines, c.stats.hatch_length_mm);
  std::printf("marked on %s, %s corners, %.0f mm/s: %.4f s (device), %zu strokes, jumps %.1f mm\n",
              job.head.name.c_str(), std::string(to_string(job.pen.corner)).c_str(), job.pen.mark_speed_mm_s,
              r.mark.mark_time_s, r.plan.strokes, r.plan.jump_length_mm);
  std::printf("read by %s: %s", v.reader.c_str(), v.decoded ? "decoded" : "NOT decoded");
  if (v.decoded)
    std::printf(", data %s: '%s'", v.data_match ? "matches" : "DIFFERS", printable_bytes(v.decoded_data).c_str());
  std::printf("\n");
  if (v.module_x_um) {
    std::printf("module %.1f", *v.module_x_um);
    if (v.module_y_um)
      std::printf(" x %.1f µm, axial non-uniformity %.1f %% (%c)", *v.module_y_um, *v.axial_nonuniformity_pct,
                  axial_nonuniformity_grade(*v.axial_nonuniformity_pct));
    else
      std::printf(" µm");
    std::printf(", ");
  }
  std::printf("fill %.0f %% (least %.0f %%), spill %.1f %%, %zu modules wrong, camera %.0f µm/px\n",
              100 * v.fill_ratio, 100 * v.fill_ratio_min, 100 * v.spill_ratio, v.modules_wrong, v.camera_px_um);
  if (!dose_png.empty()) std::printf("wrote %s\n", dose_png.c_str());
}

}  // namespace

Command make_code_command() {
  auto a = std::make_shared<CodeArgs>();
  return Command(
      [a](CLI::App& app) {
        auto* sub = app.add_subcommand("code", "mark one 2-D code or barcode on the simulated scanner and read it back");
        sub->add_option("symbology", a->symbology, "datamatrix, gs1-datamatrix, qr, code128, gs1-128")->required();
        sub->add_option("data", a->data, "data to encode (GS1: (01)09506000134352(17)261231(10)LOT42(21)SN1)")->required();
        sub->add_flag("--escapes", a->escapes, "interpret \\G \\R \\E \\xHH \\n \\\\ in the data");
        sub->add_option("--size", a->size_mm, "symbol width without quiet zone, mm");
        sub->add_option("--module", a->module_mm, "module size, mm (default 0.25)");
        sub->add_option("--bar-height", a->bar_height_mm, "linear codes: bar height, mm (default 15 % of the width)");
        sub->add_option("--matrix-size", a->matrix_size, "Data Matrix: fixed size ROWSxCOLS, e.g. 16x16, 16x48");
        sub->add_option("--shape", a->shape, "Data Matrix automatic size: square, rectangular, any")->capture_default_str();
        sub->add_option("--qr-ecc", a->qr_ecc, "QR error correction: L, M, Q, H")->capture_default_str();
        sub->add_option("--qr-version", a->qr_version, "QR version 1..40 (0: smallest)")->capture_default_str();
        sub->add_option("--style", a->style, "modules as square (hatched), dot, line")->capture_default_str();
        sub->add_option("--dot", a->dot, "dot style: spiral or circle")->capture_default_str();
        sub->add_option("--dot-size", a->dot_size, "dot diameter as a share of the module")->capture_default_str();
        sub->add_flag("--invert", a->invert, "mark the light modules and quiet zone (dark part, marks turn light)");
        sub->add_option("--x", a->x_mm, "centre x (field frame, mm)")->capture_default_str();
        sub->add_option("--y", a->y_mm, "centre y (field frame, mm)")->capture_default_str();
        sub->add_option("--angle", a->angle_deg, "rotation of the code, degrees")->capture_default_str();
        add_hatch_options(*sub, a->hatch);
        add_pen_options(*sub, a->pen);
        sub->add_option("--beam-diameter", a->beam_diameter_mm, "1/e² beam diameter on the part, mm")->capture_default_str();
        sub->add_option("--line-width", a->line_width_mm, "material: a single line at --line-speed marks this wide, mm")
            ->capture_default_str();
        sub->add_option("--line-speed", a->line_speed_mm_s, "material: speed of that reference line, mm/s")->capture_default_str();
        sub->add_option("--pixels-per-module", a->pixels_per_module, "reader camera resolution")->capture_default_str();
        sub->add_option("--aperture", a->aperture, "verifier synthetic aperture, modules")->capture_default_str();
        sub->add_option("--preview", a->preview, "write the planned path over the dose (.png or .svg)");
        sub->add_option("--dose-png", a->dose_png, "write the part as a camera sees it (PNG, pixel size in pHYs)");
        sub->add_flag("--json", a->json, "print one JSON object with the code's figures");
        return sub;
      },
      [a] {
        const CodeJob job = make_job(*a);
        const CodeJobResult r = run_code_job(job);
        nlohmann::json j = code_to_json(r.code, job.spec, r.verification);
        j["mark_time_s"] = r.mark.mark_time_s;
        j["jump_length_mm"] = r.plan.jump_length_mm;
        j["strokes"] = r.plan.strokes;
        j["head"] = job.head.name;
        j["corner"] = std::string(to_string(job.pen.corner));
        j["speed_mm_s"] = job.pen.mark_speed_mm_s;
        if (!a->preview.empty()) write_mark_preview(r.plan, r.scanner->dose(), a->preview);
        if (!a->dose_png.empty()) {
          const double margin = 2 * r.code.module_mm + job.verify.response.spot_diameter_mm;
          const FieldWindow w{r.code.bounds.min.x() - margin, r.code.bounds.min.y() - margin,
                              r.code.bounds.max.x() + margin, r.code.bounds.max.y() + margin};
          const CameraImage picture = part_picture(r.scanner->dose(), w, job.verify.response, job.layout.invert);
          write_grey_png(picture, a->dose_png);
          j["dose_px_um"] = 1e6 / pixels_per_metre(picture.pixel_mm) ;
        }
        if (a->json)
          std::cout << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
        else
          print_summary(job, r, a->dose_png);
        return r.verification.data_match ? 0 : 2;
      });
}

}  // namespace mark::cli
