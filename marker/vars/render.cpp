#include "marker/vars/render.hpp"

#include <ctime>

#include "base/error.hpp"

namespace mark {
namespace {

void render_date(const std::string& format, const MarkValues& v, std::string& out) {
  static const TimeZone utc;
  const TimeZone& zone = v.zone ? *v.zone : utc;
  std::string abbrev;
  const std::tm tm = zone.local_tm(v.now, abbrev);
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

}  // namespace

void render(const TextTemplate& t, const MarkValues& v, std::string& out) {
  for (const TemplateField& f : t.fields()) {
    switch (f.kind) {
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
        static const TimeZone utc;
        out += v.shifts->at((v.zone ? *v.zone : utc).local_seconds(v.now)).shift->code;
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
}

}  // namespace mark
