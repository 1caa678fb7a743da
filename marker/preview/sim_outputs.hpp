#pragma once
// The files a simulated mark writes besides its preview (mark_preview.hpp): the part itself
// (--dose-png) and one row per sample (--trace). `marker mark` and a production part (whose
// objects' dose and trace are added up: marker/production/part_picture.hpp) write the same.
#include <string>
#include <vector>

#include "driver/sim/dose_raster.hpp"
#include "driver/sim/mark_response.hpp"
#include "driver/sim/part_image.hpp"
#include "driver/sim/sim_trace.hpp"

namespace mark {

// The part as marked, at the dose raster's pixel, over everything the beam dosed (0.2 mm
// around it); `dark_part`: an inverted code is marked on a dark part.
GreyImage dose_part_picture(const DoseRaster& dose, const MarkResponse& response, const PartLook& look,
                            bool dark_part);

// t_s,cmd_x_mm,cmd_y_mm,laser,beam_x_mm,beam_y_mm, one row per sample, written whole
// (marker/output/output_file.hpp; throws InputError naming the file).
void write_trace_csv(const std::vector<SimTraceRow>& rows, const std::string& path);

}  // namespace mark
