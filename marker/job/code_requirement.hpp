#pragma once
// A minimum ISO/IEC TR 29158 grade every code of a job must reach (`marker mark --require-grade`,
// a job file's "require": {"code_grade": …}), predicted on the simulated scanner before anything
// fires, the way --require-quality predicts the mark's quality. A linear code has no TR 29158
// grade: it meets any requirement by reading.
#include <optional>
#include <string>
#include <vector>

#include "marker/codes/verify.hpp"
#include "marker/job/job.hpp"

namespace mark {

// Why the codes fall short of `min_grade` (4 A … 1 D), naming the first code that does
// ("code 2 (qr 25x25): grade C (cell modulation C)"); nothing when every code meets it.
std::optional<std::string> code_grade_shortfall(const JobSpec& spec, const std::vector<PlacedCode>& codes,
                                                const std::vector<CodeVerification>& verifications, int min_grade);

// The job run on a fresh simulated scanner in virtual time (no device touched; the laser's rise
// time as the real source's) and its codes read back and graded: the shortfall, or nothing.
// Throws what run_job throws for a refused job.
std::optional<std::string> predicted_code_grade_shortfall(const JobSpec& spec, int min_grade,
                                                          double laser_rise_s = 0);
// The same for a job already planned for a sample-level device (planned once, for the quality
// prediction and the run as well).
std::optional<std::string> predicted_code_grade_shortfall(const JobSpec& spec, const CompiledJob& job, int min_grade,
                                                          double laser_rise_s = 0);

}  // namespace mark
