#include "driver/lmc/lmc_open.hpp"

#include "driver/lmc/capture_link.hpp"
#include "driver/lmc/usb_discovery.hpp"

namespace mark::lmc {

std::optional<LmcSpec> parse_lmc_spec(std::string_view spec) {
  const auto forms = " (use lmc, lmc:SERIAL with the serial `marker devices` lists, or "
                     "lmc-capture:FILE)";
  LmcSpec s;
  if (spec == "lmc") return s;
  if (spec.starts_with("lmc-capture:")) {
    s.capture = true;
    s.file = std::string(spec.substr(12));
    if (s.file.empty()) throw DeviceError("--device '" + std::string(spec) + "': no file" + forms);
    return s;
  }
  if (spec.starts_with("lmc:")) {
    s.serial = std::string(spec.substr(4));
    if (!parse_serial(s.serial))
      throw DeviceError("--device '" + std::string(spec) + "': a board serial is 1 to 8 hex digits" +
                        forms);
    return s;
  }
  if (spec.starts_with("lmc")) throw DeviceError("--device '" + std::string(spec) + "' is malformed" + forms);
  return std::nullopt;
}

std::unique_ptr<LmcDevice> open_lmc(const LmcSpec& spec, LmcOptions options) {
  std::unique_ptr<LmcLink> link;
  if (spec.capture) link = std::make_unique<CaptureLink>(spec.file);
  else link = open_usb_board(spec.serial);
  return std::make_unique<LmcDevice>(std::move(link), std::move(options));
}

}  // namespace mark::lmc
