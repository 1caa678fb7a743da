#include "marker/gravure/cell_setup.hpp"

#include "marker/limits/gravure_settings.hpp"

namespace mark {

void validate(const CellSetup& s, const std::string& name) {
  check_range(name + " full-cell depth", s.full_cell_depth_um, kCellDepthBounds.range());
  check_range(name + " channel depth", s.channel_depth_um, kChannelDepthBounds.range());
  check_range(name + " gain", s.gain, kSetupGainBounds.range());
  check_range(name + " offset", s.offset_um, kSetupOffsetBounds.range());
}

void validate(const GravureSetup& s) {
  validate(s.ct, "CT");
  validate(s.lw, "LW");
  check_range("stylus lift", s.lift_um, kLift.range());
}

}  // namespace mark
