#include "marker/job/part_texts.hpp"

#include <algorithm>

#include "fonts/catalog.hpp"
#include "fonts/error.hpp"
#include "marker/vars/render.hpp"

namespace mark {

std::map<std::string, std::string> job_variables(const JobFile& job,
                                                 const std::map<std::string, std::string>& sets) {
  std::map<std::string, std::string> values = job.variables;
  std::vector<std::string> used;
  for (const JobObject& o : job.objects)
    if (const TextObject* t = o.text())
      for (const std::string& v : t->text.variables()) used.push_back(v);
  for (const auto& [name, value] : sets) {
    if (std::find(used.begin(), used.end(), name) == used.end())
      throw InputError("--set " + name + "=…: no template of " + job.source + " uses {var:" + name + "}");
    values[name] = value;
  }
  return values;
}

std::vector<ObjectText> render_objects(const JobFile& job,
                                       const std::map<std::string, std::string>& variables,
                                       SysTime now,
                                       const std::map<std::string, std::int64_t>& serials) {
  MarkValues v;
  v.now = now;
  v.zone = &job.time_zone;
  v.shifts = &job.shifts;
  v.variables = &variables;
  v.counters = &job.counters;
  v.serials = &serials;
  std::vector<ObjectText> texts;
  for (const JobObject& o : job.objects)
    if (const TextObject* t = o.text()) texts.push_back({o.name, render(t->text, v)});
  return texts;
}

JobFonts::JobFonts(const JobFile& job, std::vector<std::string>* warnings) {
  for (const JobObject& o : job.objects) {
    const TextObject* t = o.text();
    if (!t || fonts_.count(t->font)) continue;
    Warnings w;
    try {
      fonts_[t->font] = open_font(t->font, &w);
    } catch (const InputError& e) {
      throw InputError(job.source + ": object \"" + o.name + "\": " + e.what());
    }
    if (warnings) warnings->insert(warnings->end(), w.begin(), w.end());
  }
}

JobSpec object_spec(const JobFile& job, const JobObject& object, const std::string& text,
                    const JobFonts& fonts) {
  const TextObject& t = *object.text();
  const JobPen& pen = job.pens.at(object.pen);
  JobSpec spec;
  spec.text = text;
  spec.font = fonts.font(t.font);
  spec.layout = t.layout;
  spec.head = job.head;
  spec.pen = pen.motion;
  spec.order = t.order;
  return spec;
}

}  // namespace mark
