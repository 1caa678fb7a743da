#pragma once
// Verification of a marked code from a camera's picture of it — whatever took the picture: the
// job runner hands over the simulated reader's picture of the simulated part (marker/job/), a
// plant could hand over a real camera's. Three real decoders read it (code_reader.hpp; a linear
// code with its known angle undone first), and a code passes when the readers the job names
// decode exactly the data meant: by default any two of those that read the symbology agree on
// it (or the one, where only one does), and no reader read anything else. A 2-D code is graded
// after ISO/IEC TR 29158 (iso_grade.hpp) on the picture through the synthetic aperture.
//
// Against the intended module grid, fitted to the picture: how many modules come out on the
// wrong side of the threshold; with the part's own marked share (a simulated part) also how
// much of each module meant to be marked is marked (fill) and of those meant to stay bare
// (spill).
#include <optional>
#include <string>
#include <vector>

#include "base/grey_image.hpp"
#include "marker/codes/code_marks.hpp"
#include "marker/codes/code_spec.hpp"
#include "marker/codes/iso_grade.hpp"

namespace mark {

struct CodePicture {
  GreyImage picture;                // the camera's picture of the code and some part around it
  std::optional<GreyImage> marked;  // the part's marked share at the same pixels, 0..255
};

struct VerifyOptions {
  double aperture_modules = 0.5;  // synthetic aperture diameter (TR 29158: 50–80 % of the module)
  // Who decides: "" any two of the readers that read the symbology (or the only one), or a
  // reader's name (zxing, libdmtx, zbar): that reader alone.
  std::string reader;
};

struct ReaderOutcome {
  std::string reader;
  bool supported = false;   // reads this symbology (and size) at all
  bool decoded = false;
  bool data_match = false;  // decoded to exactly the data meant
  std::string data;
};

struct CodeVerification {
  std::string decided_by;             // "any two", "the only reader", or the reader named
  std::vector<ReaderOutcome> readers;  // every reader, in code_readers() order
  std::string reader;                 // whose module pitch is reported (the first deciding one that decoded)
  bool decoded = false;               // a deciding reader decoded something
  std::string expected_data;          // what a reader should return (GS1: the element string)
  std::string decoded_data;           // what `reader` returned
  bool data_match = false;            // the code passes (see above)
  double module_um = 0;               // intended module size
  // As `reader` measured them (decoded symbols only; y and the non-uniformity are 2-D only).
  std::optional<double> module_x_um, module_y_um, axial_nonuniformity_pct;
  // Against the part's own marked share (only when the picture came with it).
  std::optional<double> fill_ratio, fill_ratio_min, spill_ratio;
  std::size_t modules_wrong = 0;      // symbol modules on the wrong side of the threshold
  double camera_px_um = 0;            // pixel of the picture on the part
  std::optional<IsoGrade> grade;      // 2-D codes
};

CodeVerification verify_code(const PlacedCode& code, const CodeSpec& spec, const CodePicture& picture,
                             const VerifyOptions& options = {});

// Throws InputError when `reader` (VerifyOptions::reader) names no reader, or one that does not
// read this code; `option` is how the user gave it ("--reader", a job file's key).
void check_reader_choice(const std::string& reader, const PlacedCode& code, const std::string& option);

// Whether a verification meets a minimum grade (4 A … 1 D): empty when it does, else why not in
// a few words ("grade C (cell modulation C, unused error correction C)", "not decoded").
std::optional<std::string> grade_shortfall(const CodeVerification& v, int min_grade);

}  // namespace mark
