#include "marker/job/code_photo.hpp"

namespace mark {

FieldWindow code_window(const PlacedCode& code, const MarkResponse& response) {
  const double margin = 2 * code.module_mm + response.spot_diameter_mm;
  return {code.bounds.min.x() - margin, code.bounds.min.y() - margin, code.bounds.max.x() + margin,
          code.bounds.max.y() + margin};
}

CodePicture code_picture(const PlacedCode& code, const DoseRaster& dose, const CodeCheckOptions& o) {
  // An inverted code is for a dark part whose marks turn light: the camera sees that.
  // The part's own marked share at eight pixels a module or finer, for the fill and spill figures.
  PartPhoto photo =
      photograph(dose, code_window(code, o.response), o.response, o.camera, code.layout.invert, code.module_mm / 8);
  return {std::move(photo.picture), std::move(photo.marked)};
}

CodeVerification check_code(const PlacedCode& code, const CodeSpec& spec, const DoseRaster& dose,
                            const CodeCheckOptions& o) {
  return verify_code(code, spec, code_picture(code, dose, o), o.reading);
}

}  // namespace mark
