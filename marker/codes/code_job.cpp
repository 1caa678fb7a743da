#include "marker/codes/code_job.hpp"

#include "marker/job/job_checks.hpp"
#include "marker/layout/layout.hpp"

namespace mark {

PlacedCode place_encoded(const CodeSpec& spec, const CodeLayout& layout) {
  return place_code(encode_code(spec), layout);
}

CodeJobResult run_code_job(const CodeJob& job) {
  CodeJobResult r;
  check_pen(job.pen, job.head);
  r.code = place_encoded(job.spec, job.layout);
  // The quiet zone belongs to the code: it must fit in the field too.
  require_inside(r.code.bounds, Field{job.head.field_mm}, "the code with its quiet zone");
  r.plan = plan_figure(code_figure(r.code), job.pen);
  check_plan(r.plan, job.head);
  r.scanner = std::make_unique<SimScanner>(simulator_options(job.head, job.pen));
  r.mark = simulate_plan(r.plan, *r.scanner);
  r.verification = verify_code(r.code, job.spec, r.scanner->dose(), job.verify);
  return r;
}

}  // namespace mark
