#include "marker/job/job_compiler.hpp"

#include "fonts/error.hpp"
#include "marker/job/device_program.hpp"
#include "marker/job/job_checks.hpp"
#include "marker/plan/passes.hpp"

namespace mark {

JobCompiler::JobCompiler(JobSpec spec, DeviceLevel level)
    : spec_(std::move(spec)),
      level_(level),
      replanner_(planning_pen(spec_.pen, level), spec_.order) {}

CompiledJob JobCompiler::compile(std::string_view text, const Point& home) {
  if (text.empty()) throw InputError("the text to mark is empty");
  if (!spec_.font) throw InputError("no font given for the text to mark");
  if (spec_.passes < 1 || spec_.passes > 100)
    throw InputError("passes " + std::to_string(spec_.passes) + " is outside 1 to 100");
  check_pen(spec_.pen, spec_.head);
  CompiledJob job;
  job.level = level_;
  relayout_text(text, *spec_.font, spec_.layout, figure_);
  // The letters themselves first, so the message says which part leaves the field.
  if (!figure_.bounds().empty())
    require_inside(figure_.bounds(), Field{spec_.head.field_mm}, "the text layout");
  job.figure = figure_;
  if ((home - home_).norm() > 0) {
    home_ = home;
    replanner_ = Replanner(planning_pen(spec_.pen, level_), spec_.order, home_);
  }
  job.plan = replanner_.update(figure_);
  job.plan.pen = spec_.pen;  // command level: the delays the board applies, reported with the plan
  repeat_passes(job.plan, spec_.passes);
  check_plan(job.plan, spec_.head);
  job.laser_on_ticks = spec_.pen.ticks(spec_.pen.laser_on_delay_s);
  job.laser_off_ticks = spec_.pen.ticks(spec_.pen.laser_off_delay_s);
  return job;
}

}  // namespace mark
