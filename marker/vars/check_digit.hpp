#pragma once
// Check characters a template computes over the text it has rendered ({check:ALGO}): what
// traceability marks carry so a reader (or a person typing the number) catches a misread or
// mistyped character. Each algorithm as its standard defines it, tested against the standard's
// published examples (tests/marker/vars/check_digit_test.cpp).
//
//   luhn           ISO/IEC 7812-1 (Luhn): digits; 0–9
//   mod10          GS1 (GTIN, SSCC): digits weighted 3, 1 from the right; 0–9
//   mod11          weights 2, 3, 4, … from the right, (11 − sum mod 11) mod 11, 10 → X (ISBN-10)
//   iso7064-11-2   ISO 7064 MOD 11-2 (pure): digits; 0–9 or X (ORCID, ISO 27729 ISNI)
//   iso7064-37-36  ISO 7064 MOD 37,36 (hybrid): 0–9 A–Z; 0–9 A–Z (GRid)
//   vin            ISO 3779 / 49 CFR 565 position 9 of a 17-character VIN: over the 8 characters
//                  before it and the 8 after (I, O, Q not allowed); 0–9 or X
//
// The check covers the text the template rendered before the field (from its start or the
// previous check field), spaces and hyphens skipped as the human-readable separators they are;
// `vin` covers the whole 17 characters. A character the algorithm does not take is an error
// naming it, never a silently wrong check.
#include <optional>
#include <string>
#include <string_view>

namespace mark {

enum class CheckDigit { luhn, mod10, mod11, iso7064_11_2, iso7064_37_36, vin };

std::optional<CheckDigit> parse_check_digit(std::string_view name);
std::string_view to_string(CheckDigit c);
// "luhn, mod10, mod11, iso7064-11-2, iso7064-37-36, vin": for messages.
std::string check_digit_names();

// The check character for `covered` (`after`: the text after the field, used by `vin` only).
// Throws InputError("{check:luhn}: 'A' at character 3 is not a digit") and the like.
char check_character(CheckDigit algorithm, std::string_view covered, std::string_view after = {});

}  // namespace mark
