#include "marker/production/text_repeats.hpp"

#include "marker/production/part_texts.hpp"

namespace mark {
namespace {

// Whether the template's date fields together name the day of the year and the year: a
// counter that restarts every day repeats its texts unless they do.
bool names_the_day(const TextTemplate& t) {
  bool day = false, year = false;
  for (const TemplateField& f : t.fields()) {
    if (f.kind != FieldKind::date) continue;
    bool month = false, day_of_month = false;
    for (std::size_t i = 0; i + 1 < f.text.size(); ++i) {
      if (f.text[i] != '%') continue;
      const char c = f.text[++i];
      if (c == 'F' || c == 'D' || c == 'x' || c == 'c') day = year = true;
      if (c == 'j') day = true;
      if (c == 'd' || c == 'e') day_of_month = true;
      if (c == 'm' || c == 'b' || c == 'B' || c == 'h') month = true;
      if (c == 'Y' || c == 'y' || c == 'G' || c == 'g') year = true;
    }
    day = day || (month && day_of_month);
  }
  return day && year;
}

}  // namespace

std::vector<std::string> text_repeat_warnings(const JobFile& job) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < job.objects.size(); ++i) {
    const TextTemplate& t = job.objects[i].text_template();
    for (const std::string& name : t.counters()) {
      const CounterSpec& c = job.counters.at(name);
      std::string why;
      if (c.reset == ResetRule::midnight && !names_the_day(t))
        why = "restarts every midnight and no date field names the day (and year)";
      else if (c.reset == ResetRule::shift && (!names_the_day(t) || !t.uses(FieldKind::shift)))
        why = "restarts at every shift start and the template does not name both the day (a date field "
              "with day and year) and the shift ({shift})";
      else if (c.at_limit == EndPolicy::wrap && !names_the_day(t))
        why = "wraps to " + std::to_string(c.start) + " after " + std::to_string(c.effective_limit()) +
              " and no date field names the day";
      if (why.empty()) continue;
      out.push_back(object_place(job, i) + "counter \"" + name + "\" " + why +
                    ": its texts repeat, and the store refuses a part whose text was marked before "
                    "(add {date:%y%j}, or a date format naming day and year)");
    }
  }
  return out;
}

}  // namespace mark
