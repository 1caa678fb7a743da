#pragma once
// One part of a job file: every object's text rendered from the values the part consumed, and
// each object as a JobSpec (its font opened once per job, its pen, the job's head).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "fonts/stroke_font.hpp"
#include "marker/job/job.hpp"
#include "marker/job/job_file.hpp"
#include "marker/store/audit_row.hpp"

namespace mark {

// The job's variable defaults with `sets` on top; throws InputError for a --set naming a
// variable no template uses (a typo must not go unnoticed).
std::map<std::string, std::string> job_variables(const JobFile& job,
                                                 const std::map<std::string, std::string>& sets);

std::vector<ObjectText> render_objects(const JobFile& job,
                                       const std::map<std::string, std::string>& variables,
                                       SysTime now,
                                       const std::map<std::string, std::int64_t>& serials);

class JobFonts {
 public:
  // Opens every object's font (warnings to `warnings`); throws InputError naming the object.
  JobFonts(const JobFile& job, std::vector<std::string>* warnings = nullptr);
  std::shared_ptr<const StrokeFont> font(const std::string& name) const { return fonts_.at(name); }

 private:
  std::map<std::string, std::shared_ptr<const StrokeFont>> fonts_;
};

JobSpec object_spec(const JobFile& job, const JobObject& object, const std::string& text,
                    const JobFonts& fonts);

}  // namespace mark
