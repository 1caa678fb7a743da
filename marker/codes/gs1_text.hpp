#pragma once
// GS1 data as people write it — "(01)09506000134352(17)261231(10)LOT42(21)SN0001", or with
// square brackets — and as a reader returns it: the element string, application identifiers
// and their data run together, a GS (0x1D, what FNC1 decodes to) after every field whose length
// is not predefined by its AI, except the last. zint validates and encodes GS1 data; this only
// splits the text so the decoded data can be compared with what was meant.
#include <string>
#include <string_view>
#include <vector>

namespace mark {

struct Gs1Field {
  std::string ai;    // 2 to 4 digits
  std::string data;
};

// Throws InputError naming the position and what is wrong (no opening bracket, an AI that is
// not 2–4 digits, an empty field, brackets that do not match).
std::vector<Gs1Field> parse_gs1_text(std::string_view text);

// AIs whose data length is predefined (GS1 General Specifications, the table of element strings
// with predefined length: 00–04, 11–20, 31–36, 41 by their first two digits) need no separator.
bool gs1_length_predefined(std::string_view ai);

// The element string a reader returns (without the leading FNC1).
std::string gs1_element_string(const std::vector<Gs1Field>& fields);

}  // namespace mark
