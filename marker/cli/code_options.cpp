#include "marker/cli/code_options.hpp"

#include "fonts/error.hpp"
#include "marker/codes/code_data.hpp"
#include "marker/common/range_check.hpp"

namespace mark::cli {

void add_code_options(CLI::App& app, CodeArgs& a, const std::string& p) {
  const auto o = [&](const char* name) { return "--" + p + name; };
  app.add_flag(o("escapes"), a.escapes, "interpret \\G \\R \\E \\xHH \\n \\\\ in the code's data");
  app.add_option(o("size"), a.size_mm, "code: symbol width without quiet zone, mm");
  app.add_option(o("module"), a.module_mm, "code: module size, mm (default 0.25)");
  app.add_option(o("bar-height"), a.bar_height_mm, "linear codes: bar height, mm (default 15 % of the width)");
  app.add_option(o("matrix-size"), a.matrix_size, "Data Matrix: fixed size ROWSxCOLS, e.g. 16x16, 16x48");
  app.add_option(o("shape"), a.shape, "Data Matrix automatic size: square, rectangular, any")->capture_default_str();
  app.add_option(o("qr-ecc"), a.qr_ecc, "QR error correction: L, M, Q, H")->capture_default_str();
  app.add_option(o("qr-version"), a.qr_version, "QR version 1..40 (0: smallest)")->capture_default_str();
  app.add_option(o("style"), a.style, "code modules as square (hatched), dot, line")->capture_default_str();
  app.add_option(o("dot"), a.dot, "dot style: spiral or circle")->capture_default_str();
  app.add_option(o("dot-size"), a.dot_size, "dot diameter as a share of the module")->capture_default_str();
  app.add_flag(o("invert"), a.invert, "mark the code's light modules and quiet zone (dark part, marks turn light)");
  app.add_option(o("x"), a.x_mm, "code centre x (field frame, mm)")->capture_default_str();
  app.add_option(o("y"), a.y_mm, "code centre y (field frame, mm)")->capture_default_str();
  app.add_option(o("angle"), a.angle_deg, "rotation of the code, degrees")->capture_default_str();
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
  if (a.size_mm) require_in_range(name("size"), *a.size_mm, 0.05, 500, "mm");
  if (a.module_mm) require_in_range(name("module"), *a.module_mm, 0.01, 20, "mm");
  if (a.bar_height_mm) require_in_range(name("bar-height"), *a.bar_height_mm, 0.1, 500, "mm");
  if (a.size_mm && a.module_mm) throw InputError("give " + name("size") + " or " + name("module") + ", not both");
  require_in_range(name("x"), a.x_mm, -1000, 1000, "mm");
  require_in_range(name("y"), a.y_mm, -1000, 1000, "mm");
  require_in_range(name("angle"), a.angle_deg, -360, 360, "deg");
  require_in_range(name("dot-size"), a.dot_size, 0.2, 1.5, "modules");
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
  app.add_option("--beam-diameter", a.beam_diameter_mm, "1/e² beam diameter on the part, mm (its radius insets every fill)")
      ->capture_default_str();
  app.add_option("--line-width", a.line_width_mm, "material: a single line at --line-speed marks this wide, mm")
      ->capture_default_str();
  app.add_option("--line-speed", a.line_speed_mm_s, "material: speed of that reference line, mm/s")->capture_default_str();
  app.add_option("--pixels-per-module", a.pixels_per_module, "code reader: camera pixels per module")->capture_default_str();
  app.add_option("--aperture", a.aperture, "code reader: synthetic aperture, modules")->capture_default_str();
}

VerifyOptions to_verify_options(const VerifyArgs& a) {
  require_in_range("--beam-diameter", a.beam_diameter_mm, 0.001, 5, "mm");
  require_in_range("--line-width", a.line_width_mm, 0.001, 3 * a.beam_diameter_mm, "mm");
  require_in_range("--line-speed", a.line_speed_mm_s, 1, 100000, "mm/s");
  require_in_range("--pixels-per-module", a.pixels_per_module, 3, 20);
  require_in_range("--aperture", a.aperture, 0, 1.5, "modules");
  VerifyOptions v;
  v.response = {a.beam_diameter_mm, a.line_speed_mm_s, a.line_width_mm};
  v.pixels_per_module = a.pixels_per_module;
  v.aperture_modules = a.aperture;
  return v;
}

}  // namespace mark::cli
