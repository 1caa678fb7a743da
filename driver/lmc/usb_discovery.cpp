#include "driver/lmc/usb_discovery.hpp"

#include <algorithm>
#include <cctype>
#include <tuple>

namespace mark::lmc {
namespace {

std::string port_path(libusb_device* d) {
  std::uint8_t ports[8];
  const int n = libusb_get_port_numbers(d, ports, 8);
  std::string s = std::to_string(libusb_get_bus_number(d));
  for (int i = 0; i < n; ++i) {
    s += i ? '.' : '-';
    s += std::to_string(ports[i]);
  }
  return s;
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// GetSerialNo on an opened link: the board's answer, w1 w2.
std::string ask_serial(LmcLink& link) {
  link.write(bytes(word(Op::GetSerialNo)));
  return serial_string(decode_reply(link.read()));
}

struct DeviceList {
  libusb_device** list = nullptr;
  ssize_t n = 0;
  explicit DeviceList(libusb_context* ctx) {
    n = libusb_get_device_list(ctx, &list);
    if (n < 0) throw usb_error(int(n), "cannot list USB devices");
  }
  ~DeviceList() {
    if (list) libusb_free_device_list(list, 1);
  }
};

}  // namespace

std::vector<UsbBoardInfo> list_usb_boards(bool read_serials, UsbLinkOptions options) {
  auto ctx = std::make_shared<UsbContext>();
  DeviceList devices(ctx->get());
  std::vector<UsbBoardInfo> out;
  for (ssize_t i = 0; i < devices.n; ++i) {
    libusb_device* d = devices.list[i];
    libusb_device_descriptor desc{};
    if (libusb_get_device_descriptor(d, &desc) != 0 || desc.idVendor != kVendorId) continue;
    if (desc.idProduct != kProductId && desc.idProduct != kCloneProductId) continue;
    UsbBoardInfo info;
    info.bus = libusb_get_bus_number(d);
    info.address = libusb_get_device_address(d);
    info.port_path = port_path(d);
    info.vendor_id = desc.idVendor;
    info.product_id = desc.idProduct;
    if (desc.idProduct == kCloneProductId) {
      info.note = "unflashed clone board: needs its firmware loaded (EzCad's driver does it)";
    } else if (read_serials) {
      try {
        UsbLink link(ctx, d, options);
        info.serial = ask_serial(link);
        info.usable = true;
      } catch (const std::exception& e) {
        info.note = e.what();
      }
    } else {
      info.usable = true;
    }
    out.push_back(std::move(info));
  }
  std::sort(out.begin(), out.end(), [](const UsbBoardInfo& a, const UsbBoardInfo& b) {
    return std::tie(a.bus, a.address) < std::tie(b.bus, b.address);
  });
  return out;
}

std::unique_ptr<UsbLink> open_usb_board(const std::string& serial, UsbLinkOptions options) {
  auto ctx = std::make_shared<UsbContext>();
  DeviceList devices(ctx->get());
  std::vector<std::string> seen;
  std::unique_ptr<UsbLink> found;
  std::string failures;
  for (ssize_t i = 0; i < devices.n; ++i) {
    libusb_device* d = devices.list[i];
    libusb_device_descriptor desc{};
    if (libusb_get_device_descriptor(d, &desc) != 0 || desc.idVendor != kVendorId ||
        desc.idProduct != kProductId)
      continue;
    std::unique_ptr<UsbLink> link;
    std::string s;
    try {
      link = std::make_unique<UsbLink>(ctx, d, options);
      s = ask_serial(*link);
    } catch (const std::exception& e) {
      failures += std::string("; ") + e.what();
      continue;
    }
    link->set_serial(s);
    seen.push_back(s);
    if (!serial.empty() && upper(s) != upper(serial)) continue;
    if (found)
      throw LinkError(LinkFailure::no_device,
                      "lmc: several boards found (serials " + seen.front() + ", " + s +
                          "): choose one with --device lmc:SERIAL");
    found = std::move(link);
  }
  if (found) return found;
  std::string msg = serial.empty() ? "lmc: no LMC board (USB 9588:9899) found"
                                   : "lmc: no LMC board with serial " + serial + " found";
  if (!seen.empty()) {
    msg += " (found:";
    for (const std::string& s : seen) msg += " " + s;
    msg += ")";
  }
  throw LinkError(LinkFailure::no_device, msg + failures);
}

}  // namespace mark::lmc
