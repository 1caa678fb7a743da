#pragma once
// One code's figures as JSON, the same object for `marker code --json` and for each entry of
// `marker mark --json`'s "codes" list (fields and units in docs/codes.md).
#include <nlohmann/json.hpp>

#include "marker/codes/code_marks.hpp"
#include "marker/codes/code_spec.hpp"
#include "marker/codes/verify.hpp"

namespace mark {

nlohmann::json code_to_json(const PlacedCode& code, const CodeSpec& spec, const CodeVerification& v);
// The ISO/IEC TR 29158 grade of a 2-D code (code_to_json's "iso").
nlohmann::json iso_grade_json(const IsoGrade& grade);

}  // namespace mark
