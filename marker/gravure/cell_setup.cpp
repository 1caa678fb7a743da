#include "marker/gravure/cell_setup.hpp"

#include "marker/gravure/parameter_range.hpp"

namespace mark {

void validate(const CellSetup& s, const std::string& name) {
  check_range(name + " full-cell depth", s.full_cell_depth_um, kCellDepthRange);
  check_range(name + " channel depth", s.channel_depth_um, kChannelDepthRange);
  check_range(name + " gain", s.gain, kSetupGainRange);
  check_range(name + " offset", s.offset_um, kSetupOffsetRange);
}

void validate(const GravureSetup& s) {
  validate(s.ct, "CT");
  validate(s.lw, "LW");
  check_range("stylus lift", s.lift_um, kLiftRange);
}

}  // namespace mark
