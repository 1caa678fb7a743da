#pragma once
// A text template: literal text with fields in braces.
//
//   {NAME}                 the value of counter NAME (its own alphabet, width and padding)
//   {NAME:OPT:OPT…}        … with OPT = an alphabet (decimal, hex, base36, base33), a width in
//                          digits (1..64), or a padding (keep, suppress, blank), in any order:
//                          {serial:base36:8}
//   {date} {date:FORMAT}   the date and time in the job's time zone, strftime FORMAT
//                          (default %Y-%m-%d): {date:%y%j} is year and day of the year
//   {var:NAME}             a value set from outside for each mark (--set NAME=VALUE)
//   {col:NAME}             column NAME of the part's row of the job's data list (a CSV file)
//   {shift}                the code of the shift running now (the job's shift start times)
//   {datecode:NAME}        the code of date-code table NAME for now (the job's "date_codes", or
//                          the built-in vin-year; date_codes.hpp)
//   {check:ALGO}           a check character over the text before it (luhn, mod10, mod11,
//                          iso7064-11-2, iso7064-37-36, vin; check_digit.hpp)
//   {{ and }}              literal braces
//
// Parsing checks the syntax; whether a counter or variable exists is the job's business.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "marker/vars/alphabet.hpp"

namespace mark {

enum class FieldKind { literal, counter, date, var, shift, column, datecode, check };

struct TemplateField {
  FieldKind kind = FieldKind::literal;
  std::string text;  // literal text, counter name, date format, variable, table or algorithm name
  // Counter fields: overrides of the counter's own formatting.
  std::optional<Alphabet> alphabet;
  std::optional<int> width;
  std::optional<Padding> padding;
};

class TextTemplate {
 public:
  TextTemplate() = default;
  // Throws InputError("<where>: '<source>' at character N: <problem>").
  static TextTemplate parse(std::string_view source, std::string_view where);

  const std::string& source() const { return source_; }
  const std::vector<TemplateField>& fields() const { return fields_; }
  // Names used, each once, in order of first use.
  std::vector<std::string> counters() const;
  std::vector<std::string> variables() const;
  std::vector<std::string> columns() const;  // {col:NAME}
  std::vector<std::string> date_code_tables() const;  // {datecode:NAME}
  bool uses(FieldKind kind) const;
  // No fields besides literal text: the same text for every part.
  bool constant() const;

 private:
  std::string source_;
  std::vector<TemplateField> fields_;
};

// Characters a date format may use after '%' (the C/POSIX strftime conversions that do not
// depend on the locale's modifiers E and O).
bool valid_date_format(std::string_view format, std::string* problem);

}  // namespace mark
