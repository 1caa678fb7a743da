#include "marker/cli/code_options.hpp"

#include "base/error.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/codes/code_data.hpp"
#include "marker/limits/code_settings.hpp"

namespace mark::cli {

void add_code_options(CLI::App& app, CodeArgs& a, const std::string& p) {
  add_setting(app, kCodeEscapes, a.escapes, p);
  add_setting(app, kCodeSize, a.size_mm, p);
  add_setting(app, kModule, a.module_mm, p);
  add_setting(app, kBarHeight, a.bar_height_mm, p);
  add_setting(app, kMatrixSize, a.matrix_size, p);
  add_setting(app, kMatrixShape, a.shape, p);
  add_setting(app, kQrEcc, a.qr_ecc, p);
  add_setting(app, kQrVersion, a.qr_version, p);
  add_setting(app, kModuleStyle, a.style, p);
  add_setting(app, kDotShape, a.dot, p);
  add_setting(app, kDotSize, a.dot_size, p);
  add_setting(app, kCodeInvert, a.invert, p);
  add_setting(app, kCodeX, a.x_mm, p);
  add_setting(app, kCodeY, a.y_mm, p);
  add_setting(app, kCodeAngle, a.angle_deg, p);
}

CodeObject to_code_object(const std::string& symbology, const std::string& data, const CodeArgs& a,
                          const FillOptions& hatch, const std::string& p) {
  const auto name = [&](const char* n) { return "--" + p + n; };
  CodeObject c;
  c.spec.symbology = parse_symbology(symbology);
  c.spec.data = a.escapes ? unescape_code_data(data) : data;
  if (!a.matrix_size.empty()) parse_matrix_size(a.matrix_size, c.spec.matrix_rows, c.spec.matrix_cols);
  c.spec.shape = parse_matrix_shape(a.shape);
  if (!kQrEcc.allows(a.qr_ecc))
    throw InputError(name("qr-ecc") + " '" + a.qr_ecc + "' is not one of " + std::string(kQrEcc.choices));
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
  add_setting(app, kBeamDiameter, a.beam_diameter_mm);
  add_setting(app, kLineWidth, a.line_width_mm);
  add_setting(app, kLineSpeed, a.line_speed_mm_s);
  add_setting(app, kPixelsPerModule, a.pixels_per_module);
  add_setting(app, kAperture, a.aperture);
}

VerifyOptions to_verify_options(const VerifyArgs& a) {
  // Each value was checked while parsing; the line width also depends on the beam.
  check_range(kLineWidth.name.flag, a.line_width_mm, limited_range(kLineWidth, 3 * a.beam_diameter_mm, "3 beam diameters"));
  VerifyOptions v;
  v.response = {a.beam_diameter_mm, a.line_speed_mm_s, a.line_width_mm};
  v.pixels_per_module = a.pixels_per_module;
  v.aperture_modules = a.aperture;
  return v;
}

}  // namespace mark::cli
