#pragma once
// What `marker tool-measure` (and `marker gcode --tool-image`) reports about a measured cutter:
// the same figures as lines of text or as JSON, every angle with its axis and direction.
#include <nlohmann/json.hpp>
#include <ostream>

#include "marker/cli/option_ranges.hpp"
#include "marker/cnc/tool/tool_measure.hpp"

namespace mark::cli {

// Where the form deviation's angle is measured from (the same words in the text and in docs/).
inline constexpr const char* kAngleConvention =
    "counter-clockwise from the image's +x axis (pointing right), y up";

nlohmann::json tool_measurement_json(const ToolMeasurement& m, const ToolMeasureOptions& options);
void print_tool_measurement(std::ostream& out, const ToolMeasurement& m, const ToolMeasureOptions& options);

}  // namespace mark::cli
