#pragma once
// The options of one code — its encoding and its layout — and of reading codes back (material,
// camera, aperture), shared by `marker code` (names as they are: --module, --x) and
// `marker mark` (prefixed: --code-module, --code-x, next to the text's own options).
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "marker/codes/code_object.hpp"
#include "marker/codes/verify.hpp"
#include "marker/fill/fill_options.hpp"

namespace mark::cli {

struct CodeArgs {
  bool escapes = false;
  std::optional<double> size_mm, module_mm, bar_height_mm;
  std::string matrix_size;
  std::string shape = "square";
  std::string qr_ecc = "M";
  int qr_version = 0;
  std::string style = "square";
  std::string dot = "spiral";
  double dot_size = 1.0;
  bool invert = false;
  double x_mm = 0, y_mm = 0, angle_deg = 0;
};

// `prefix` is put before every option name: "" or "code-".
void add_code_options(CLI::App& app, CodeArgs& args, const std::string& prefix);

// The code to mark; `hatch` fills square modules. Throws InputError naming the (prefixed) option.
CodeObject to_code_object(const std::string& symbology, const std::string& data, const CodeArgs& args,
                          const FillOptions& hatch, const std::string& prefix);

struct VerifyArgs {
  double beam_diameter_mm = 0.04;
  double line_width_mm = 0.04;
  double line_speed_mm_s = 1000;
  double pixels_per_module = 7;
  double aperture = 0.5;
};

void add_verify_options(CLI::App& app, VerifyArgs& args);
VerifyOptions to_verify_options(const VerifyArgs& args);

}  // namespace mark::cli
