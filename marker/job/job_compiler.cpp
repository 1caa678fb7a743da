#include "marker/job/job_compiler.hpp"

#include "base/error.hpp"
#include "marker/job/device_program.hpp"
#include "marker/job/job_checks.hpp"
#include "marker/plan/passes.hpp"

namespace mark {

void check_text(const JobSpec& spec, std::string_view text) {
  if (text.empty() && spec.codes.empty()) throw InputError("the text to mark is empty");
  if (!text.empty() && !spec.font) throw InputError("no font given for the text to mark");
  if (spec.passes < 1 || spec.passes > 100)
    throw InputError("passes " + std::to_string(spec.passes) + " is outside 1 to 100");
}

void check_layout(const Figure& figure, const JobSpec& spec, std::string_view remedy) {
  // The letters themselves first, so the message says which part leaves the field.
  if (!figure.bounds().empty())
    require_inside(figure.bounds(), Field{spec.head.field_mm}, "the text layout", remedy);
}

void complete_plan(CompiledJob& job, const JobSpec& spec) {
  repeat_passes(job.plan, spec.passes);
  check_plan(job.plan, spec.head);
  job.laser_on_ticks = spec.pen.ticks(spec.pen.laser_on_delay_s);
  job.laser_off_ticks = spec.pen.ticks(spec.pen.laser_off_delay_s);
}

JobCompiler::JobCompiler(JobSpec spec, DeviceLevel level, bool code_escapes)
    : spec_(std::move(spec)), level_(level), code_escapes_(code_escapes), replanner_(spec_.pen, spec_.order) {}

CompiledJob JobCompiler::compile(std::string_view text, const Point& home) {
  if (!incremental()) {
    JobSpec spec = spec_;
    set_marked_text(spec, text, code_escapes_);
    return compile_job(spec, level_, home);
  }
  check_text(spec_, text);
  check_pen(spec_.pen, spec_.head);
  CompiledJob job;
  job.level = level_;
  relayout_text(text, *spec_.font, spec_.layout, figure_);
  check_layout(figure_, spec_);
  job.figure = figure_;
  if (level_ == DeviceLevel::commands) {
    // A board jumps from wherever its mirrors are to the first absolute target: no home.
    job.plan = plan_for_device(figure_, spec_.pen, spec_.order);
  } else {
    if ((home - home_).norm() > 0) {
      home_ = home;
      replanner_ = Replanner(spec_.pen, spec_.order, home_);
    }
    job.plan = replanner_.update(figure_);
  }
  complete_plan(job, spec_);
  return job;
}

}  // namespace mark
