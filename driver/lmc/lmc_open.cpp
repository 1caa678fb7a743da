#include "driver/lmc/lmc_open.hpp"

#include "driver/lmc/capture_link.hpp"
#include "driver/lmc/usb_discovery.hpp"

namespace mark::lmc {

std::unique_ptr<LmcDevice> open_lmc(const LmcSpec& spec, LmcOptions options) {
  std::unique_ptr<LmcLink> link;
  if (spec.capture) link = std::make_unique<CaptureLink>(spec.file);
  else link = open_usb_board(spec.serial);
  return std::make_unique<LmcDevice>(std::move(link), std::move(options));
}

}  // namespace mark::lmc
