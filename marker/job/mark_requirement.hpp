#pragma once
// What a mark must be to count as good, judged on what the evaluator read back: every code
// decodes to exactly its data (always), the mark reaches a least quality class
// (`mark --require-quality`, a job object's "require": {"quality": …}) and every code a least
// ISO/IEC TR 29158 grade (`--require-grade`, "require": {"code_grade": …}). The same judgement
// runs twice: on a fresh simulated scanner before anything fires (the prediction), and on the
// part as marked (the verdict, marker/production/part_verdict.hpp). A linear code has no
// TR 29158 grade: it meets any grade by reading.
#include <optional>
#include <string>
#include <vector>

#include "driver/sim/quality_class.hpp"
#include "marker/codes/verify.hpp"
#include "marker/job/job.hpp"

namespace mark {

struct MarkRequirement {
  std::optional<QualityClass> quality;  // none: any class
  int code_grade = 0;                   // 0: none; 4 A … 1 D
  // Whether anything beyond reading the codes is asked (what needs a prediction).
  bool any() const { return quality.has_value() || code_grade > 0; }
};

// Why the codes fall short of `min_grade` (4 A … 1 D), naming the first code that does
// ("code 2 (qr 25x25): grade C (cell modulation C)"); nothing when every code meets it.
std::optional<std::string> code_grade_shortfall(const JobSpec& spec, const std::vector<PlacedCode>& codes,
                                                const std::vector<CodeVerification>& verifications, int min_grade);

// Why a marked job falls short of `require`, the first reason of: a code not read back to its
// data ("code 2 not decoded by any two (modules wrong: 113)"), the quality class ("quality poor,
// below good (max deviation 55.0 µm, coverage 97.00 %, dose ratio 1.67)"), a code's grade.
// Nothing when it meets it. Only what was read back is judged: a result without quality figures
// or code read-backs (a device with no evaluator) has nothing to fall short of.
std::optional<std::string> requirement_shortfall(const JobSpec& spec, const JobResult& marked,
                                                 const MarkRequirement& require);

// The job run on a fresh simulated scanner in virtual time (no device touched; the laser's rise
// time as the real source's), judged: the shortfall, or nothing. `job` is planned for a
// sample-level device. Throws what run_job throws for a refused job.
std::optional<std::string> predicted_shortfall(const JobSpec& spec, const CompiledJob& job,
                                               const MarkRequirement& require, double laser_rise_s = 0);

}  // namespace mark
