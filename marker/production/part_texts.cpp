#include "marker/production/part_texts.hpp"

#include <algorithm>

#include "base/error.hpp"
#include "fonts/catalog.hpp"
#include "marker/codes/code_data.hpp"
#include "marker/vars/render.hpp"

namespace mark {

std::map<std::string, std::string> job_variables(const JobFile& job,
                                                 const std::map<std::string, std::string>& sets) {
  std::map<std::string, std::string> values = job.variables;
  std::vector<std::string> used;
  for (const JobObject& o : job.objects)
    for (const std::string& v : o.text_template().variables()) used.push_back(v);
  for (const auto& [name, value] : sets) {
    if (std::find(used.begin(), used.end(), name) == used.end()) {
      // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on the chained operator+.
      std::string msg = "--set ";
      msg.append(name).append("=…: no template of ").append(job.source);
      msg.append(" uses {var:").append(name).append("}");
      throw InputError(msg);
    }
    values[name] = value;
  }
  return values;
}

std::vector<ObjectText> render_objects(const JobFile& job,
                                       const std::map<std::string, std::string>& variables,
                                       SysTime now,
                                       const std::map<std::string, std::int64_t>& serials,
                                       const std::map<std::string, std::string>* columns) {
  MarkValues v;
  v.now = now;
  v.zone = &job.time_zone;
  v.shifts = &job.shifts;
  v.variables = &variables;
  v.counters = &job.counters;
  v.serials = &serials;
  v.columns = columns;
  v.date_codes = &job.date_codes;
  std::vector<ObjectText> texts;
  for (std::size_t i = 0; i < job.objects.size(); ++i) {
    const JobObject& o = job.objects[i];
    try {
      texts.push_back({o.name, render(o.text_template(), v), o.text_template().uses(FieldKind::counter)});
    } catch (const InputError& e) {
      throw InputError(object_place(job, i) + e.what());
    }
  }
  return texts;
}

std::vector<ObjectText> first_part_texts(const JobFile& job,
                                         const std::map<std::string, std::string>& variables,
                                         SysTime now, std::map<std::string, std::int64_t>* serials,
                                         const DataList* data,
                                         const std::map<std::string, std::int64_t>* values,
                                         std::size_t data_row) {
  std::map<std::string, std::int64_t> starts;
  for (const auto& [name, spec] : job.used_counters()) starts[name] = spec.start;
  if (values)
    for (const auto& [name, value] : *values) starts[name] = value;
  auto vars = variables;
  for (const std::string& v : job.required_variables())
    if (!vars.count(v)) vars[v] = "<" + v + ">";
  std::map<std::string, std::string> columns;
  if (data && data_row < data->size()) columns = data->values(data_row);
  for (const JobObject& o : job.objects)
    for (const std::string& c : o.text_template().columns())
      if (!columns.count(c)) columns[c] = "<" + c + ">";
  std::vector<ObjectText> texts = render_objects(job, vars, now, starts, &columns);
  if (serials) *serials = std::move(starts);
  return texts;
}

std::map<std::string, std::int64_t> next_serials(const JobFile& job, SerialStore& store, SysTime now) {
  std::map<std::string, std::int64_t> values;
  for (const auto& [name, spec] : job.used_counters()) {
    const CounterStatus st = store.status(name, &spec, job.shifts, now);
    if (!st.known) {
      values[name] = spec.start;
      continue;
    }
    if (!st.next) throw InputError("counter " + name + " has stopped (its limit was reached): no next part");
    values[name] = *st.next;
  }
  return values;
}

DataList load_data_list(const JobFile& job) {
  if (!job.data) throw InputError(job.source + ": the job has no data list (\"data\")");
  DataList list = DataList::read(job.data->path, job.data->delimiter);
  for (std::size_t i = 0; i < job.objects.size(); ++i) {
    for (const std::string& c : job.objects[i].text_template().columns()) {
      if (list.column(c)) continue;
      std::string names;
      for (const std::string& n : list.columns()) names.append(names.empty() ? "" : ", ").append(n);
      throw InputError(object_place(job, i) + "{col:" + c + "}: the data list " + job.data->file +
                       " has no column \"" + c + "\" (its columns: " + names + ")");
    }
  }
  return list;
}

JobFonts::JobFonts(const JobFile& job, std::vector<std::string>* warnings) {
  for (const JobObject& o : job.objects) {
    const TextObject* t = o.text();
    if (!t || fonts_.count(t->font)) continue;
    Warnings w;
    try {
      fonts_[t->font] = open_font(t->font, &w);
    } catch (const InputError& e) {
      std::string msg = job.source;
      msg.append(": object \"").append(o.name).append("\": ").append(e.what());
      throw InputError(msg);
    }
    if (warnings) warnings->insert(warnings->end(), w.begin(), w.end());
  }
}

JobSpec object_spec(const JobFile& job, const JobObject& object, const std::string& text,
                    const JobFonts& fonts) {
  const JobPen& pen = job.pens.at(object.pen);
  JobSpec spec;
  spec.head = job.head;
  spec.pen = pen.motion;
  spec.laser = pen.laser;
  spec.passes = pen.passes;
  // The head's spot is the beam the codes are read back with (and a line of its width at 1 m/s).
  spec.verify.response.spot_diameter_mm = spec.verify.response.reference_width_mm =
      job.head.spot_diameter_um / 1000;
  if (const TextObject* t = object.text()) {
    spec.font = fonts.font(t->font);
    spec.layout = t->layout;
    spec.order = t->order;
    spec.fill = t->fill;
  } else {
    spec.codes.push_back(object.code()->code);
  }
  set_marked_text(spec, text, object.code() && object.code()->escapes);
  return spec;
}

std::string object_place(const JobFile& job, std::size_t i) {
  std::string place = job.source;
  place.append(": objects[").append(std::to_string(i)).append("] \"");
  place.append(job.objects.at(i).name).append("\": ");
  return place;
}

}  // namespace mark
