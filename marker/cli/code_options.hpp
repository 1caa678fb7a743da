#pragma once
// The options of one code — its encoding and its layout — and of reading codes back (material,
// camera, aperture), shared by `marker code` (names as they are: --module, --x) and
// `marker mark` (prefixed: --code-module, --code-x, next to the text's own options).
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "marker/codes/code_object.hpp"
#include "marker/job/code_photo.hpp"
#include "marker/fill/fill_options.hpp"
#include "marker/limits/code_settings.hpp"

namespace mark::cli {

struct CodeArgs {
  // Defaults from the settings table (marker/limits/code_settings.hpp).
  bool escapes = false;
  std::optional<double> size_mm, module_mm, bar_height_mm;
  std::string matrix_size;
  std::string shape{kMatrixShape.value};
  std::string qr_ecc{kQrEcc.value};
  int qr_version = static_cast<int>(*kQrVersion.value);
  std::string style{kModuleStyle.value};
  std::string dot{kDotShape.value};
  double dot_size = *kDotSize.value;
  bool invert = false;
  double x_mm = *kCodeX.value, y_mm = *kCodeY.value, angle_deg = *kCodeAngle.value;
};

// `prefix` is put before every option name: "" or "code-".
void add_code_options(CLI::App& app, CodeArgs& args, const std::string& prefix);

// The code to mark; `hatch` fills square modules. Throws InputError naming the (prefixed) option.
CodeObject to_code_object(const std::string& symbology, const std::string& data, const CodeArgs& args,
                          const FillOptions& hatch, const std::string& prefix);

struct VerifyArgs {
  double beam_diameter_mm = *kBeamDiameter.value;
  double line_width_mm = *kLineWidth.value;
  double line_speed_mm_s = *kLineSpeed.value;
  double aperture = *kAperture.value;
  std::string camera;  // KEY=VALUE,… over the default reader's camera
  std::string reader;  // "" (any two agree) or zxing, libdmtx, zbar
  std::string dose_reference{kDoseReference.value};  // pen or material
};

void add_verify_options(CLI::App& app, VerifyArgs& args);
CodeCheckOptions to_verify_options(const VerifyArgs& args);

// --camera KEY=VALUE,…: the default camera with the keys given changed, each checked against its
// range. Throws InputError naming the key (an unknown one with the list of keys).
CameraSettings parse_camera_option(const std::string& text);
// The keys, their units, ranges and defaults, one per line (for --help and docs/codes.md).
std::string camera_keys_help();

// --require-grade A|B|C|D → 4..1. Throws InputError otherwise.
int parse_required_grade(const std::string& text, const std::string& option);

}  // namespace mark::cli
