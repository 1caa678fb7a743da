#pragma once
// Finding LMC boards: every USB device with the BJJCZ vendor id and the board's product id
// (0x9588:0x9899), with its bus, address and board serial (GetSerialNo, which needs the board
// opened: a board another program holds, or one the user may not open, is listed with a note
// instead). Unflashed clones (0x9588:0x9980) are listed as unusable.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "driver/lmc/usb_link.hpp"

namespace mark::lmc {

struct UsbBoardInfo {
  int bus = 0;
  int address = 0;
  std::string port_path;  // "1-2.3": stable while the cable stays in the same port
  std::uint16_t vendor_id = 0, product_id = 0;
  std::optional<std::string> serial;
  bool usable = false;    // could be opened and answered GetSerialNo
  std::string note;       // why not, when not
};

// All boards on the system. read_serials = false skips opening them.
std::vector<UsbBoardInfo> list_usb_boards(bool read_serials = true,
                                          UsbLinkOptions options = {});

// Opens the board with this serial (case-insensitive), or the only board when `serial` is
// empty. Throws LinkError (no_device) naming what was found when there is no unique match.
std::unique_ptr<UsbLink> open_usb_board(const std::string& serial, UsbLinkOptions options = {});

}  // namespace mark::lmc
