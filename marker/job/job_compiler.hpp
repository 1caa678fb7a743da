#pragma once
// Compiling the parts of a series: one spec (font, layout, pen, head, passes) and a new text per
// part. The text is laid out again only where it changed (relayout_text: the font's shapes are
// computed once, unchanged glyphs are kept) and planned again only from the first changed glyph
// (Replanner; a command-level device's plan is made whole), with every refusal of compile_job.
// The result equals a fresh compile_job of the same text.
//
// The plan starts where the mirrors are (`home`): a device that marks one job after another
// leaves them where the last job ended, and a sample-level job's first jump (its length, the
// settling after it) is planned from there. A new home plans the text again from its first glyph.
#include <string_view>

#include "marker/job/job.hpp"
#include "marker/plan/replan.hpp"

namespace mark {

// The steps compile_job and JobCompiler share: the spec's refusals before the layout (text,
// font, passes), the layout's (the letters leave the field; `remedy` ends the message), and the
// plan's completion (passes, laser delay ticks) with its refusals (speeds, field). The pen is
// checked against the head (check_pen, job_checks.hpp) before planning.
void check_text(const JobSpec& spec, std::string_view text);
void check_layout(const Figure& figure, const JobSpec& spec, std::string_view remedy = {});
void complete_plan(CompiledJob& job, const JobSpec& spec);

class JobCompiler {
 public:
  // spec.text (or its code's data) is not used; each compile() brings its own. A code object's
  // data has its escapes decoded when `code_escapes`.
  JobCompiler(JobSpec spec, DeviceLevel level, bool code_escapes = false);

  // Throws InputError (or MissingGlyphError) naming the problem; a refused text leaves the
  // compiler ready for the next.
  CompiledJob compile(std::string_view text, const Point& home = Point(0, 0));

  const JobSpec& spec() const { return spec_; }
  DeviceLevel level() const { return level_; }
  // Glyphs planned again by the last compile (for tests and benchmarks).
  std::size_t replanned_glyphs() const { return replanner_.replanned_glyphs(); }

 private:
  // Plain text (no fill, no code) compiles from the last part's layout and plan; a filled text
  // or a code is laid out and planned whole each time (compile_job).
  bool incremental() const { return spec_.codes.empty() && !spec_.fill; }

  JobSpec spec_;
  DeviceLevel level_;
  bool code_escapes_;
  Figure figure_;        // the last layout, the base of the next
  Point home_{0, 0};
  Replanner replanner_;  // the last plan, likewise
};

}  // namespace mark
