#pragma once
// The objects of a part are compiled one by one, each alone in the field; only here do they
// meet. A reader needs a code's quiet zone bare, and two objects whose inks touch mark one blur:
// both are refused before the part fires (job check, and every part inside its allocation, so a
// refused part consumes nothing), naming both objects and where.
#include <vector>

#include "marker/job/job.hpp"
#include "marker/production/job_file.hpp"

namespace mark {

// Throws InputError for the first pair of objects (in object order) where one's ink lies in
// the other's code quiet zone, or two inks come closer than the spot diameter (their marks
// touch), unless the job lays the two over each other on purpose (an object's "overlaps"; never a
// code's quiet zone). `compiled[i]` is object i as compiled for this part. Ink is sampled every 0.05 mm along
// each lit element, so inks closer than the spot by less than that may pass; nothing is refused
// that does not touch.
void check_objects_apart(const JobFile& job, const std::vector<CompiledJob>& compiled);

}  // namespace mark
