#include "driver/lmc/masked_link.hpp"

namespace mark::lmc {

const char* MaskedLink::fires(const Word& w) const {
  switch (static_cast<Op>(w.opcode())) {
    case Op::WritePort:
    case Op::ListWritePort: return (w.p(1) & laser_mask_) ? "sets the laser bit of the output port" : nullptr;
    case Op::FiberSetMo:
    case Op::FiberOpenMO: return w.p(1) ? "opens the master oscillator" : nullptr;
    case Op::EnableLaser: return "enables the laser";
    case Op::LaserSignalOn: return "switches the laser signal on";
    case Op::LaserOnPoint: return "fires a dot";
    default: return nullptr;
  }
}

void MaskedLink::write(std::span<const std::uint8_t> bytes) {
  for (std::size_t at = 0; at + kCommandBytes <= bytes.size(); at += kCommandBytes) {
    const Word w = load(bytes.data() + at);
    if (const char* why = fires(w)) {
      ++refused_;
      throw LinkError(LinkFailure::io, "lmc: refused before it was sent, the laser is masked off: " +
                                           std::string(command_name(w.opcode())) + " " + why);
    }
  }
  inner_.write(bytes);
}

}  // namespace mark::lmc
