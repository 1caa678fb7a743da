#include "driver/lmc/lmc_open.hpp"

#include "driver/lmc/capture_link.hpp"
#include "driver/lmc/usb_discovery.hpp"

namespace mark::lmc {

BoardOptions emulated_board_options(const LmcOptions& options) {
  BoardOptions b;
  b.field_mm = options.field_mm;
  b.axes = options.axes;
  b.laser_bit = options.laser_port_bit;
  b.red_bit = options.red_pointer_bit;
  return b;
}

std::unique_ptr<LmcLink> open_lmc_link(const LmcSpec& spec, const LmcOptions& options, const EmulatedSetup& emulated) {
  if (spec.capture) return std::make_unique<CaptureLink>(spec.file);
  if (spec.emulated) {
    BoardOptions b = emulated_board_options(options);
    b.scanner = emulated.scanner;
    return std::make_unique<EmulatedLink>(b, spec.variant, emulated.virtual_clock);
  }
  return open_usb_board(spec.serial);
}

std::unique_ptr<LmcDevice> open_lmc(const LmcSpec& spec, LmcOptions options, const EmulatedSetup& emulated) {
  return std::make_unique<LmcDevice>(open_lmc_link(spec, options, emulated), std::move(options));
}

}  // namespace mark::lmc
