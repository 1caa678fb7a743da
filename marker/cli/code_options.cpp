#include "marker/cli/code_options.hpp"

#include <algorithm>
#include <cmath>

#include "base/error.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/codes/code_data.hpp"
#include "marker/cli/option_values.hpp"
#include "marker/codes/code_reader.hpp"
#include "marker/cli/number_keys.hpp"
#include "marker/limits/camera_limits.hpp"
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

namespace {

// One --camera key: its name, range, the setting it sets and what it means.
struct CameraKey {
  const char* name;
  const Range* range;
  void (*set)(CameraSettings&, double);
  double (*get)(const CameraSettings&);
  const char* help;
};

#define CAMERA_KEY(NAME, RANGE, FIELD, HELP)                                                        \
  CameraKey {                                                                                       \
    NAME, &RANGE, [](CameraSettings& s, double v) { s.FIELD = static_cast<decltype(s.FIELD)>(v); }, \
        [](const CameraSettings& s) { return static_cast<double>(s.FIELD); }, HELP                  \
  }

const std::vector<CameraKey>& camera_keys() {
  static const std::vector<CameraKey> keys{
      CAMERA_KEY("pixel_um", kCameraPixelRange, pixel_um,
                 "pixel on the part (0: the code's window fills the sensor; a multiple of 5 µm)"),
      CAMERA_KEY("min_pixel_um", kCameraMinPixelRange, min_pixel_um, "finest pixel on the part (closest focus)"),
      CAMERA_KEY("sensor_width_px", kSensorSideRange, sensor_width_px, "sensor width"),
      CAMERA_KEY("sensor_height_px", kSensorSideRange, sensor_height_px, "sensor height"),
      CAMERA_KEY("sensor_pixel_um", kSensorPixelRange, sensor_pixel_um, "sensor pixel pitch"),
      CAMERA_KEY("f_number", kFNumberRange, f_number, "working f-number (diffraction blur)"),
      CAMERA_KEY("wavelength_nm", kWavelengthRange, wavelength_nm, "illumination wavelength"),
      CAMERA_KEY("defocus_um", kDefocusRange, defocus_um, "defocus blur disc diameter on the part"),
      CAMERA_KEY("falloff_pct", kFalloffRange, falloff_pct, "illumination lost at the sensor's corners"),
      CAMERA_KEY("exposure_pct", kExposureRange, exposure_pct, "the lighter surface at this share of full scale"),
      CAMERA_KEY("full_well_ke", kFullWellRange, full_well_ke, "electrons at full scale (shot noise)"),
      CAMERA_KEY("read_noise_grey", kReadNoiseRange, read_noise_grey, "read noise, rms grey levels"),
      CAMERA_KEY("seed", kNoiseSeedRange, seed, "sensor noise seed"),
      CAMERA_KEY("bare_reflectance", kReflectanceRange, look.bare_reflectance, "bare part (a dark part: its marks)"),
      CAMERA_KEY("mark_reflectance", kReflectanceRange, look.mark_reflectance, "fully darkened mark (a dark part: bare)"),
      CAMERA_KEY("tone_ratio", kToneRatioRange, look.tone_ratio, "fluence ratio from a half to a fully dark mark"),
      CAMERA_KEY("grain_pct", kGrainRange, look.grain_pct, "rms reflectance grain of the surface"),
      CAMERA_KEY("noise_seed", kNoiseSeedRange, look.seed, "surface grain seed"),
  };
  return keys;
}

#undef CAMERA_KEY

}  // namespace

CameraSettings parse_camera_option(const std::string& text) {
  CameraSettings s;
  const auto& keys = camera_keys();
  std::vector<NumberKey> names;
  for (const CameraKey& k : keys) names.push_back({k.name, k.range, k.range == &kNoiseSeedRange});
  for (const auto& [k, v] : parse_number_keys("--camera", text, names, "pixel_um=20,defocus_um=40"))
    keys[k].set(s, v);
  return s;
}

std::string camera_keys_help() {
  std::string out;
  const CameraSettings defaults;
  for (const CameraKey& k : camera_keys())
    out += std::string(k.name) + " (" + k.range->text() + ", default " + format_number(k.get(defaults)) + "): " + k.help + "\n";
  return out;
}

int parse_required_grade(const std::string& text, const std::string& option) {
  const int g = text.size() == 1 ? parse_grade(text.front()) : -1;
  if (g < 1) throw InputError(option + " '" + text + "' is not one of A, B, C, D");
  return g;
}

void add_verify_options(CLI::App& app, VerifyArgs& a) {
  add_setting(app, kBeamDiameter, a.beam_diameter_mm);
  add_setting(app, kLineWidth, a.line_width_mm);
  add_setting(app, kLineSpeed, a.line_speed_mm_s);
  add_setting(app, kDoseReference, a.dose_reference);
  add_setting(app, kAperture, a.aperture);
  add_setting(app, kCamera, a.camera);
  add_setting(app, kCodeReader, a.reader);
}

CodeCheckOptions to_verify_options(const VerifyArgs& a) {
  // Each value was checked while parsing; the line width also depends on the beam.
  check_range(kLineWidth.name.flag, a.line_width_mm, limited_range(kLineWidth, 3 * a.beam_diameter_mm, "3 beam diameters"));
  CodeCheckOptions v;
  v.response = {a.beam_diameter_mm, a.line_speed_mm_s, a.line_width_mm};
  v.camera = parse_camera_option(a.camera);
  v.reading.aperture_modules = a.aperture;
  v.reading.reader = a.reader;
  v.dose_vs_material = a.dose_reference == "material";
  if (!a.reader.empty()) named_code_reader(a.reader, "--reader");
  return v;
}

}  // namespace mark::cli
