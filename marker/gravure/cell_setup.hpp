#pragma once
// Setup values of the engraver (US 6,007,230, FIG. 5A blocks 81–90): one set for continuous
// tone (CT), one for line-work (LW), each giving the two scalers the control points use —
//
//   full-cell depth scaler   centre depth  = offset + gain · full_cell_depth · D
//   channel depth scaler     entry / exit  = offset + gain · channel_depth · d
//
// D the cell's (or sub-cell's) total density, d one density value, both 0 .. 1. The channel is
// the groove that joins neighbouring dark cells along the track: where the stylus does not leave
// the copper between them. Line-work is usually cut with deeper channels than tone so lines
// and type print solid.
#include <string>

namespace mark {

struct CellSetup {
  double full_cell_depth_um = 40;  // depth of a 100 % cell
  double channel_depth_um = 8;     // depth at the cell boundary between 100 % cells
  double gain = 1;                 // video gain on the density
  double offset_um = 0;            // added to every engraved depth (stylus touch-down calibration)

  double full_cell_depth(double density) const { return offset_um + gain * full_cell_depth_um * density; }
  double channel_depth(double density) const { return offset_um + gain * channel_depth_um * density; }
};

struct GravureSetup {
  CellSetup ct;                                 // continuous tone
  CellSetup lw{30, 16, 1, 0};                   // line-work: shallower cells, deeper channels
  double lift_um = 5;                           // stylus height above the surface over white
};

// Throws InputError naming the field ("CT full-cell depth 500: outside 1 .. 200 µm").
void validate(const CellSetup& setup, const std::string& name);
void validate(const GravureSetup& setup);

}  // namespace mark
