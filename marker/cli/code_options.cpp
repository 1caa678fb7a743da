#include "marker/cli/code_options.hpp"

#include "base/error.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/codes/code_data.hpp"
#include "marker/limits/code_limits.hpp"

namespace mark::cli {

void add_code_options(CLI::App& app, CodeArgs& a, const std::string& p) {
  const auto o = [&](const char* name) { return "--" + p + name; };
  app.add_flag(o("escapes"), a.escapes, "interpret \\G \\R \\E \\xHH \\n \\\\ in the code's data");
  add_ranged_option(app, o("size"), a.size_mm, "code: symbol width without quiet zone, mm", kCodeSizeRange);
  add_ranged_option(app, o("module"), a.module_mm, "code: module size, mm (default 0.25)", kModuleRange);
  add_ranged_option(app, o("bar-height"), a.bar_height_mm, "linear codes: bar height, mm (default 15 % of the width)",
                    kBarHeightRange);
  app.add_option(o("matrix-size"), a.matrix_size, "Data Matrix: fixed size ROWSxCOLS, e.g. 16x16, 16x48");
  app.add_option(o("shape"), a.shape, "Data Matrix automatic size: square, rectangular, any")->capture_default_str();
  app.add_option(o("qr-ecc"), a.qr_ecc, "QR error correction: L, M, Q, H")->capture_default_str();
  add_ranged_option(app, o("qr-version"), a.qr_version, "QR version (0: the smallest that holds the data)",
                    kQrVersionRange)->capture_default_str();
  app.add_option(o("style"), a.style, "code modules as square (hatched), dot, line")->capture_default_str();
  app.add_option(o("dot"), a.dot, "dot style: spiral or circle")->capture_default_str();
  add_ranged_option(app, o("dot-size"), a.dot_size, "dot diameter as a share of the module", kDotShareRange)
      ->capture_default_str();
  app.add_flag(o("invert"), a.invert, "mark the code's light modules and quiet zone (dark part, marks turn light)");
  add_ranged_option(app, o("x"), a.x_mm, "code centre x (field frame, mm)", kCodePositionRange)->capture_default_str();
  add_ranged_option(app, o("y"), a.y_mm, "code centre y (field frame, mm)", kCodePositionRange)->capture_default_str();
  add_ranged_option(app, o("angle"), a.angle_deg, "rotation of the code, degrees", kCodeAngleRange)
      ->capture_default_str();
}

CodeObject to_code_object(const std::string& symbology, const std::string& data, const CodeArgs& a,
                          const FillOptions& hatch, const std::string& p) {
  const auto name = [&](const char* n) { return "--" + p + n; };
  CodeObject c;
  c.spec.symbology = parse_symbology(symbology);
  c.spec.data = a.escapes ? unescape_code_data(data) : data;
  if (!a.matrix_size.empty()) parse_matrix_size(a.matrix_size, c.spec.matrix_rows, c.spec.matrix_cols);
  c.spec.shape = parse_matrix_shape(a.shape);
  if (a.qr_ecc.size() != 1) throw InputError(name("qr-ecc") + " '" + a.qr_ecc + "' is not one of L, M, Q, H");
  c.spec.qr_ecc = a.qr_ecc.front();
  c.spec.qr_version = a.qr_version;

  CodeLayout& l = c.layout;
  // Given means given: 0 is not "automatic" on the command line.
  if (a.size_mm && a.module_mm) throw InputError("give " + name("size") + " or " + name("module") + ", not both");
  l.size_mm = a.size_mm.value_or(0);
  l.module_mm = a.module_mm.value_or(0);
  l.bar_height_mm = a.bar_height_mm.value_or(0);
  l.center = Point(a.x_mm, a.y_mm);
  l.angle_deg = a.angle_deg;
  l.style = parse_module_style(a.style);
  l.dot = parse_dot_shape(a.dot);
  l.dot_share = a.dot_size;
  l.invert = a.invert;
  l.fill = hatch;
  return c;
}

void add_verify_options(CLI::App& app, VerifyArgs& a) {
  add_ranged_option(app, "--beam-diameter", a.beam_diameter_mm,
                    "1/e² beam diameter on the part, mm (its radius insets every fill)", kBeamDiameterRange)
      ->capture_default_str();
  add_ranged_option(app, "--line-width", a.line_width_mm,
                    "material: a single line at --line-speed marks this wide, mm (at most 3 beam diameters)",
                    kLineWidthRange)
      ->capture_default_str();
  add_ranged_option(app, "--line-speed", a.line_speed_mm_s, "material: speed of that reference line, mm/s",
                    kLineSpeedRange)
      ->capture_default_str();
  add_ranged_option(app, "--pixels-per-module", a.pixels_per_module, "code reader: camera pixels per module",
                    kPixelsPerModuleRange)
      ->capture_default_str();
  add_ranged_option(app, "--aperture", a.aperture, "code reader: synthetic aperture, modules", kApertureRange)
      ->capture_default_str();
}

VerifyOptions to_verify_options(const VerifyArgs& a) {
  // Each value was checked while parsing; the line width also depends on the beam.
  check_range("--line-width", a.line_width_mm,
              Range{kLineWidthRange.min, 3 * a.beam_diameter_mm, "mm (3 beam diameters)"});
  VerifyOptions v;
  v.response = {a.beam_diameter_mm, a.line_speed_mm_s, a.line_width_mm};
  v.pixels_per_module = a.pixels_per_module;
  v.aperture_modules = a.aperture;
  return v;
}

}  // namespace mark::cli
