#include "marker/vars/render.hpp"

#include <ctime>
#include <vector>

#include "base/error.hpp"
#include "marker/vars/check_digit.hpp"

namespace mark {
namespace {

const TimeZone& zone_of(const MarkValues& v) {
  static const TimeZone utc;
  return v.zone ? *v.zone : utc;
}

void render_date(const std::string& format, const MarkValues& v, std::string& out) {
  std::string abbrev;
  const std::tm tm = zone_of(v).local_tm(v.now, abbrev);
  char buf[256];
  const std::size_t n = std::strftime(buf, sizeof buf, format.c_str(), &tm);
  if (n == 0 && !format.empty())
    throw InputError("{date:" + format + "}: the formatted date is empty or longer than 255 bytes");
  out.append(buf, n);
}

template <class Map>
const typename Map::mapped_type* find(const Map* map, const std::string& key) {
  if (!map) return nullptr;
  const auto it = map->find(key);
  return it == map->end() ? nullptr : &it->second;
}

void render_date_code(const std::string& name, const MarkValues& v, std::string& out) {
  const DateCodeTable* table = find(v.date_codes, name);
  if (!table) table = builtin_date_code_table(name);
  if (!table) throw InputError("{datecode:" + name + "}: no date-code table named \"" + name + "\" in \"date_codes\"");
  std::string abbrev;
  out += date_code(*table, name, zone_of(v).local_tm(v.now, abbrev));
}

struct PendingCheck {
  CheckDigit algorithm;
  std::size_t at;  // where in `out` it goes, before any check is inserted
};

// Each check over the text since the template's start (or the check before it), left to right,
// inserted where its field stood.
void insert_checks(const std::vector<PendingCheck>& checks, std::size_t start, std::string& out) {
  std::size_t from = start, shift = 0;
  for (const PendingCheck& c : checks) {
    const std::size_t at = c.at + shift;
    const char check = check_character(c.algorithm, std::string_view(out).substr(from, at - from),
                                       std::string_view(out).substr(at));
    out.insert(at, 1, check);
    from = at + 1;
    ++shift;
  }
}

}  // namespace

void render(const TextTemplate& t, const MarkValues& v, std::string& out) {
  const std::size_t start = out.size();
  std::vector<PendingCheck> checks;
  for (const TemplateField& f : t.fields()) {
    switch (f.kind) {
      case FieldKind::datecode: render_date_code(f.text, v, out); break;
      case FieldKind::check: checks.push_back({*parse_check_digit(f.text), out.size()}); break;
      case FieldKind::literal: out += f.text; break;
      case FieldKind::date: render_date(f.text, v, out); break;
      case FieldKind::var: {
        const std::string* value = find(v.variables, f.text);
        if (!value)
          throw InputError("{var:" + f.text + "} has no value: set it with --set " + f.text + "=VALUE");
        out += *value;
        break;
      }
      case FieldKind::column: {
        const std::string* value = find(v.columns, f.text);
        if (!value)
          throw InputError("{col:" + f.text + "}: " +
                           (v.columns ? "the data list has no column \"" + f.text + "\""
                                      : std::string("the job has no data list (\"data\")")));
        out += *value;
        break;
      }
      case FieldKind::shift: {
        if (!v.shifts || v.shifts->empty())
          throw InputError("{shift} needs the job's shift start times (\"shifts\")");
        out += v.shifts->at(zone_of(v).local_seconds(v.now)).shift->code;
        break;
      }
      case FieldKind::counter: {
        const CounterSpec* spec = find(v.counters, f.text);
        if (!spec) throw InputError("{" + f.text + "}: no counter named \"" + f.text + "\"");
        const std::int64_t* value = find(v.serials, f.text);
        if (!value)
          throw InputError("{" + f.text + "}: counter \"" + f.text + "\" has no value for this part");
        (f.alphabet ? *f.alphabet : spec->alphabet)
            .format(*value, f.width.value_or(spec->width), f.padding.value_or(spec->padding), out);
        break;
      }
    }
  }
  insert_checks(checks, start, out);
}

}  // namespace mark
