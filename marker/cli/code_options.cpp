#include "marker/cli/code_options.hpp"

#include <algorithm>
#include <cmath>

#include "base/error.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/codes/code_data.hpp"
#include "marker/cli/option_values.hpp"
#include "marker/codes/code_reader.hpp"
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
  std::size_t at = 0;
  while (at <= text.size() && !text.empty()) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    const std::string item = text.substr(at, comma - at);
    at = comma + 1;
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos)
      throw InputError("--camera '" + item + "': expected KEY=VALUE, e.g. pixel_um=20,defocus_um=40");
    const std::string key = item.substr(0, eq), value = item.substr(eq + 1);
    const auto k = std::find_if(keys.begin(), keys.end(), [&](const CameraKey& c) { return key == c.name; });
    if (k == keys.end()) {
      std::string names;
      for (const CameraKey& c : keys) names += (names.empty() ? "" : ", ") + std::string(c.name);
      throw InputError("--camera: unknown key '" + key + "' (keys: " + names + ")");
    }
    const std::optional<double> v = parse_number(value);
    if (!v) throw InputError("--camera " + key + ": '" + value + "' is not a number (range: " + k->range->text() + ")");
    check_range("--camera " + key, *v, *k->range, value);
    if (k->range == &kNoiseSeedRange && *v != std::floor(*v))
      throw InputError("--camera " + key + ": '" + value + "' is not a whole number");
    k->set(s, *v);
  }
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
  add_ranged_option(app, "--aperture", a.aperture, "code verifier: synthetic aperture, modules", kApertureRange)
      ->capture_default_str();
  app.add_option("--camera", a.camera,
                 "code reader's camera: KEY=VALUE,… (keys: pixel_um, f_number, defocus_um, falloff_pct, "
                 "full_well_ke, read_noise_grey, seed, bare_reflectance, mark_reflectance, tone_ratio, "
                 "grain_pct, …; docs/codes.md)");
  app.add_option("--reader", a.reader,
                 "code reader that decides: zxing, libdmtx, zbar (default: any two that read the symbology agree)");
}

CodeCheckOptions to_verify_options(const VerifyArgs& a) {
  // Each value was checked while parsing; the line width also depends on the beam.
  check_range("--line-width", a.line_width_mm,
              Range{kLineWidthRange.min, 3 * a.beam_diameter_mm, "mm (3 beam diameters)"});
  CodeCheckOptions v;
  v.response = {a.beam_diameter_mm, a.line_speed_mm_s, a.line_width_mm};
  v.camera = parse_camera_option(a.camera);
  v.reading.aperture_modules = a.aperture;
  v.reading.reader = a.reader;
  if (!a.reader.empty()) named_code_reader(a.reader, "--reader");
  return v;
}

}  // namespace mark::cli
