#pragma once
// The libusb link to a real board (galvo.md §1.1): interface 0 claimed (a kernel driver
// detached first if one is bound), bulk OUT 0x02 and bulk IN 0x88, each transfer bounded by the
// link timeout (100 ms, as the reference drivers). Errors map to LinkFailure; nothing retries.
#include <libusb.h>

#include <cstdint>
#include <memory>
#include <string>

#include "driver/lmc/link.hpp"

namespace mark::lmc {

inline constexpr std::uint16_t kVendorId = 0x9588;
inline constexpr std::uint16_t kProductId = 0x9899;       // a running board
inline constexpr std::uint16_t kCloneProductId = 0x9980;  // an unflashed clone (needs firmware)
inline constexpr unsigned char kEndpointOut = 0x02;
inline constexpr unsigned char kEndpointIn = 0x88;

// One libusb context, shared by the links and discovery calls that use it.
class UsbContext {
 public:
  UsbContext();
  ~UsbContext();
  UsbContext(const UsbContext&) = delete;
  UsbContext& operator=(const UsbContext&) = delete;
  libusb_context* get() const { return ctx_; }

 private:
  libusb_context* ctx_ = nullptr;
};

struct UsbLinkOptions {
  double timeout_s = 0.1;
};

// The libusb error as a link failure, with a message naming the operation and the board.
LinkError usb_error(int code, const std::string& what);

class UsbLink : public LmcLink {
 public:
  // Opens and claims `device` (which must belong to `context`). Throws LinkError naming the
  // board and the reason (permission: the udev rule; busy: another program has it).
  UsbLink(std::shared_ptr<UsbContext> context, libusb_device* device, UsbLinkOptions options);
  ~UsbLink() override;

  void write(std::span<const std::uint8_t> bytes) override;
  std::array<std::uint8_t, kReplyBytes> read() override;
  void clear_halt() override;
  void reopen() override;
  std::string name() const override;

  int bus() const { return bus_; }
  int address() const { return address_; }
  // The board serial to find it again after a replug (set by whoever read it).
  void set_serial(std::string serial) { serial_ = std::move(serial); }
  void remember_serial(const std::string& serial) override { serial_ = serial; }

 private:
  void open(libusb_device* device);
  void close() noexcept;

  std::shared_ptr<UsbContext> context_;
  UsbLinkOptions options_;
  libusb_device_handle* handle_ = nullptr;
  int bus_ = 0, address_ = 0;
  std::string serial_;
};

}  // namespace mark::lmc
