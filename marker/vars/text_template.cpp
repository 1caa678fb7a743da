#include "marker/vars/text_template.hpp"

#include <algorithm>
#include <charconv>

#include "base/error.hpp"
#include "marker/vars/check_digit.hpp"

namespace mark {
namespace {

class TemplateParser {
 public:
  TemplateParser(std::string_view source, std::string_view where) : s_(source), where_(where) {}

  std::vector<TemplateField> run() {
    std::string literal;
    std::size_t i = 0;
    while (i < s_.size()) {
      const char c = s_[i];
      if (c == '{' && i + 1 < s_.size() && s_[i + 1] == '{') {
        literal += '{', i += 2;
      } else if (c == '}' && i + 1 < s_.size() && s_[i + 1] == '}') {
        literal += '}', i += 2;
      } else if (c == '}') {
        fail(i, "a lone '}' (write }} for a literal brace)");
      } else if (c == '{') {
        const std::size_t close = s_.find('}', i + 1);
        if (close == std::string_view::npos) fail(i, "'{' without a closing '}'");
        const std::string_view body = s_.substr(i + 1, close - i - 1);
        if (body.find('{') != std::string_view::npos) fail(i, "a '{' inside a field");
        if (!literal.empty()) out_.push_back({FieldKind::literal, std::move(literal), {}, {}, {}});
        literal.clear();
        out_.push_back(field(body, i));
        i = close + 1;
      } else {
        literal += c, ++i;
      }
    }
    if (!literal.empty()) out_.push_back({FieldKind::literal, std::move(literal), {}, {}, {}});
    return std::move(out_);
  }

 private:
  [[noreturn]] void fail(std::size_t at, const std::string& problem) const {
    throw InputError(std::string(where_) + ": '" + std::string(s_) + "' at character " +
                     std::to_string(at + 1) + ": " + problem);
  }

  static bool name_ok(std::string_view n) {
    if (n.empty()) return false;
    return std::all_of(n.begin(), n.end(), [](char c) {
      return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
             c == '_' || c == '-' || c == '.';
    });
  }

  TemplateField field(std::string_view body, std::size_t at) const {
    TemplateField f;
    const std::size_t colon = body.find(':');
    const std::string_view head = body.substr(0, colon);
    const std::string_view rest =
        colon == std::string_view::npos ? std::string_view{} : body.substr(colon + 1);
    if (head == "date") {
      f.kind = FieldKind::date;
      f.text = colon == std::string_view::npos ? "%Y-%m-%d" : std::string(rest);
      std::string problem;
      if (f.text.empty()) fail(at, "{date:} needs a format after the colon, e.g. {date:%y%j}");
      if (!valid_date_format(f.text, &problem)) fail(at, problem);
      return f;
    }
    if (head == "var") {
      f.kind = FieldKind::var;
      f.text = std::string(rest);
      if (!name_ok(f.text)) fail(at, "{var:NAME} needs a name of letters, digits, _ - or .");
      return f;
    }
    if (head == "col") {
      f.kind = FieldKind::column;
      f.text = std::string(rest);
      if (f.text.empty()) fail(at, "{col:NAME} needs the name of a column of the job's data list");
      return f;
    }
    if (head == "datecode") {
      f.kind = FieldKind::datecode;
      f.text = std::string(rest);
      if (!name_ok(f.text)) fail(at, "{datecode:NAME} needs the name of a date-code table (the job's \"date_codes\", or vin-year)");
      return f;
    }
    if (head == "check") {
      f.kind = FieldKind::check;
      f.text = std::string(rest);
      if (!parse_check_digit(f.text))
        fail(at, "{check:" + f.text + "}: the check is one of " + check_digit_names());
      return f;
    }
    if (head == "shift") {
      if (colon != std::string_view::npos) fail(at, "{shift} takes no options");
      f.kind = FieldKind::shift;
      return f;
    }
    if (!name_ok(head))
      fail(at, "'{" + std::string(body) +
                   "}' is not a field: use {COUNTER}, {COUNTER:OPTIONS}, {date:FORMAT}, "
                   "{var:NAME}, {col:NAME}, {shift}, {datecode:NAME} or {check:ALGO}");
    f.kind = FieldKind::counter;
    f.text = std::string(head);
    std::string_view opts = rest;
    while (colon != std::string_view::npos) {
      const std::size_t next = opts.find(':');
      const std::string_view opt = opts.substr(0, next);
      option(f, opt, at);
      if (next == std::string_view::npos) break;
      opts = opts.substr(next + 1);
    }
    return f;
  }

  void option(TemplateField& f, std::string_view opt, std::size_t at) const {
    if (opt.empty()) fail(at, "an empty option in {" + f.text + ":…}");
    if (opt[0] >= '0' && opt[0] <= '9') {
      int w = 0;
      const auto [p, ec] = std::from_chars(opt.data(), opt.data() + opt.size(), w);
      if (ec != std::errc{} || p != opt.data() + opt.size() || w < 1 || w > 64)
        fail(at, "width '" + std::string(opt) + "' is not a number of digits from 1 to 64");
      if (f.width) fail(at, "two widths in one field");
      f.width = w;
    } else if (auto a = Alphabet::named(opt)) {
      if (f.alphabet) fail(at, "two alphabets in one field");
      f.alphabet = *a;
    } else if (auto p = parse_padding(opt)) {
      if (f.padding) fail(at, "two paddings in one field");
      f.padding = *p;
    } else {
      fail(at, "'" + std::string(opt) +
                   "' is not an alphabet (decimal, hex, base36, base33), a width (1..64) or a "
                   "padding (keep, suppress, blank)");
    }
  }

  std::string_view s_;
  std::string_view where_;
  std::vector<TemplateField> out_;
};

void add_unique(std::vector<std::string>& names, const std::string& n) {
  if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
}

}  // namespace

bool valid_date_format(std::string_view f, std::string* problem) {
  static constexpr std::string_view kConversions = "aAbBcCdDeFgGhHIjmMnpRrStTuUVwWxXyYzZ%";
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (f[i] != '%') continue;
    if (i + 1 >= f.size()) {
      if (problem) *problem = "the date format ends with a lone '%'";
      return false;
    }
    if (kConversions.find(f[i + 1]) == std::string_view::npos) {
      if (problem)
        *problem = std::string("'%") + f[i + 1] +
                   "' is not a date conversion (strftime: %Y %y %m %d %j %H %M %S %U %W %V %u "
                   "%a %b …)";
      return false;
    }
    ++i;
  }
  return true;
}

TextTemplate TextTemplate::parse(std::string_view source, std::string_view where) {
  TextTemplate t;
  t.source_ = std::string(source);
  t.fields_ = TemplateParser(source, where).run();
  return t;
}

std::vector<std::string> TextTemplate::counters() const {
  std::vector<std::string> names;
  for (const TemplateField& f : fields_)
    if (f.kind == FieldKind::counter) add_unique(names, f.text);
  return names;
}

std::vector<std::string> TextTemplate::variables() const {
  std::vector<std::string> names;
  for (const TemplateField& f : fields_)
    if (f.kind == FieldKind::var) add_unique(names, f.text);
  return names;
}

std::vector<std::string> TextTemplate::columns() const {
  std::vector<std::string> names;
  for (const TemplateField& f : fields_)
    if (f.kind == FieldKind::column) add_unique(names, f.text);
  return names;
}

std::vector<std::string> TextTemplate::date_code_tables() const {
  std::vector<std::string> names;
  for (const TemplateField& f : fields_)
    if (f.kind == FieldKind::datecode) add_unique(names, f.text);
  return names;
}

bool TextTemplate::uses(FieldKind kind) const {
  return std::any_of(fields_.begin(), fields_.end(),
                     [&](const TemplateField& f) { return f.kind == kind; });
}

bool TextTemplate::constant() const {
  return std::all_of(fields_.begin(), fields_.end(),
                     [](const TemplateField& f) { return f.kind == FieldKind::literal; });
}

}  // namespace mark
