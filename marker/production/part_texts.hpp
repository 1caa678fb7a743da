#pragma once
// One part of a job file: every object's text rendered from the values the part consumed, and
// each object as a JobSpec (its font opened once per job, its pen, the job's head).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "fonts/stroke_font.hpp"
#include "marker/job/job.hpp"
#include "marker/production/job_file.hpp"
#include "marker/store/audit_row.hpp"
#include "marker/store/serial_store.hpp"
#include "marker/vars/data_list.hpp"

namespace mark {

// The job's variable defaults with `sets` on top; throws InputError for a --set naming a
// variable no template uses (a typo must not go unnoticed).
std::map<std::string, std::string> job_variables(const JobFile& job,
                                                 const std::map<std::string, std::string>& sets);

// Every object's text; an object whose template carries a counter field is marked unique (the
// store refuses a part whose such text was marked before). `columns`: the part's data-list row.
std::vector<ObjectText> render_objects(const JobFile& job,
                                       const std::map<std::string, std::string>& variables,
                                       SysTime now,
                                       const std::map<std::string, std::int64_t>& serials,
                                       const std::map<std::string, std::string>* columns = nullptr);

// The job's data list, read and checked against its templates: every {col:NAME} names a
// column. Throws InputError naming the file (and line) or the object.
DataList load_data_list(const JobFile& job);

// The texts of a first part on a fresh store (`job check`, `job new --speed auto`): every
// counter at its start (given back in `serials`), variables without a value shown as <name>,
// the data list's first row (or <column> without one). With `values`, the counters take those
// and the data list row `data_row` instead (`job check --preview`: the store's next part,
// next_serials and SerialStore::next_data_row).
std::vector<ObjectText> first_part_texts(const JobFile& job,
                                         const std::map<std::string, std::string>& variables,
                                         SysTime now,
                                         std::map<std::string, std::int64_t>* serials = nullptr,
                                         const DataList* data = nullptr,
                                         const std::map<std::string, std::int64_t>* values = nullptr,
                                         std::size_t data_row = 0);

// The values the store gives the next part from each counter the job uses, by its rules at
// `now` (nothing consumed; a counter the store does not know yet: its start). Throws InputError
// for a counter that has stopped at its limit.
std::map<std::string, std::int64_t> next_serials(const JobFile& job, SerialStore& store, SysTime now);

class JobFonts {
 public:
  // Opens every object's font (warnings to `warnings`); throws InputError naming the object.
  JobFonts(const JobFile& job, std::vector<std::string>* warnings = nullptr);
  std::shared_ptr<const StrokeFont> font(const std::string& name) const { return fonts_.at(name); }

 private:
  std::map<std::string, std::shared_ptr<const StrokeFont>> fonts_;
};

// Object i's spec: its text, font and layout, its pen's motion and laser settings and passes,
// the job's head.
JobSpec object_spec(const JobFile& job, const JobObject& object, const std::string& text,
                    const JobFonts& fonts);

// Where object i is, for messages: `job.json: objects[1] "lot": `.
std::string object_place(const JobFile& job, std::size_t i);

}  // namespace mark
