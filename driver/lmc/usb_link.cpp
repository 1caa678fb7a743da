#include "driver/lmc/usb_link.hpp"

#include <cmath>

#include "driver/lmc/usb_discovery.hpp"

namespace mark::lmc {

UsbContext::UsbContext() {
  const int rc = libusb_init(&ctx_);
  if (rc != 0) throw usb_error(rc, "libusb_init");
}

UsbContext::~UsbContext() {
  if (ctx_) libusb_exit(ctx_);
}

LinkError usb_error(int code, const std::string& what) {
  LinkFailure f = LinkFailure::io;
  std::string hint;
  switch (code) {
    case LIBUSB_ERROR_TIMEOUT: f = LinkFailure::timeout; break;
    case LIBUSB_ERROR_PIPE: f = LinkFailure::stall; break;
    case LIBUSB_ERROR_NO_DEVICE: f = LinkFailure::no_device; hint = " (unplugged?)"; break;
    case LIBUSB_ERROR_ACCESS:
      hint = " (permission denied: install packaging/udev/60-marker-lmc.rules, see README)";
      break;
    case LIBUSB_ERROR_BUSY: hint = " (another program has claimed the board)"; break;
    default: break;
  }
  return LinkError(f, "lmc: " + what + ": " + libusb_error_name(code) + hint);
}

UsbLink::UsbLink(std::shared_ptr<UsbContext> context, libusb_device* device,
                 UsbLinkOptions options)
    : context_(std::move(context)), options_(options) {
  open(device);
}

UsbLink::~UsbLink() { close(); }

void UsbLink::open(libusb_device* device) {
  bus_ = libusb_get_bus_number(device);
  address_ = libusb_get_device_address(device);
  int rc = libusb_open(device, &handle_);
  if (rc != 0) {
    handle_ = nullptr;
    throw usb_error(rc, "cannot open " + name());
  }
  // Detach a kernel driver if one is bound (none is, normally: the board has class 0xFF).
  if (libusb_kernel_driver_active(handle_, 0) == 1) {
    rc = libusb_detach_kernel_driver(handle_, 0);
    if (rc != 0 && rc != LIBUSB_ERROR_NOT_FOUND) {
      close();
      throw usb_error(rc, "cannot detach the kernel driver from " + name());
    }
  }
  int config = 0;
  if (libusb_get_configuration(handle_, &config) == 0 && config != 1) {
    rc = libusb_set_configuration(handle_, 1);
    if (rc != 0) {
      close();
      throw usb_error(rc, "cannot select configuration 1 of " + name());
    }
  }
  rc = libusb_claim_interface(handle_, 0);
  if (rc != 0) {
    close();
    throw usb_error(rc, "cannot claim interface 0 of " + name());
  }
}

void UsbLink::close() noexcept {
  if (!handle_) return;
  libusb_release_interface(handle_, 0);
  libusb_close(handle_);
  handle_ = nullptr;
}

namespace {
unsigned int timeout_ms(double s) { return static_cast<unsigned int>(std::ceil(s * 1000)); }
}  // namespace

void UsbLink::write(std::span<const std::uint8_t> bytes) {
  if (!handle_) throw LinkError(LinkFailure::no_device, "lmc: " + name() + " is closed");
  if (bytes.size() != kCommandBytes && bytes.size() != kPacketBytes)
    throw LinkError(LinkFailure::io, "lmc: refusing a transfer of " + std::to_string(bytes.size()) +
                                         " bytes (the board takes 12 or 3072)");
  int done = 0;
  const int rc = libusb_bulk_transfer(handle_, kEndpointOut, const_cast<unsigned char*>(bytes.data()),
                                      static_cast<int>(bytes.size()), &done,
                                      timeout_ms(options_.timeout_s));
  if (rc != 0) throw usb_error(rc, "write to " + name());
  if (done != static_cast<int>(bytes.size()))
    throw LinkError(LinkFailure::io, "lmc: short write to " + name() + ": " +
                                         std::to_string(done) + " of " +
                                         std::to_string(bytes.size()) + " bytes");
}

std::array<std::uint8_t, kReplyBytes> UsbLink::read() {
  if (!handle_) throw LinkError(LinkFailure::no_device, "lmc: " + name() + " is closed");
  std::array<std::uint8_t, kReplyBytes> reply{};
  int done = 0;
  const int rc = libusb_bulk_transfer(handle_, kEndpointIn, reply.data(), int(reply.size()), &done,
                                      timeout_ms(options_.timeout_s));
  if (rc != 0) throw usb_error(rc, "read from " + name());
  if (done != int(reply.size()))
    throw LinkError(LinkFailure::io, "lmc: short reply from " + name() + ": " +
                                         std::to_string(done) + " of 8 bytes");
  return reply;
}

void UsbLink::clear_halt() {
  if (!handle_) throw LinkError(LinkFailure::no_device, "lmc: " + name() + " is closed");
  for (unsigned char ep : {kEndpointOut, kEndpointIn}) {
    const int rc = libusb_clear_halt(handle_, ep);
    if (rc != 0) throw usb_error(rc, "clear halt on " + name());
  }
}

void UsbLink::reopen() {
  close();
  std::unique_ptr<UsbLink> fresh = open_usb_board(serial_, options_);
  handle_ = fresh->handle_;
  bus_ = fresh->bus_;
  address_ = fresh->address_;
  context_ = fresh->context_;
  fresh->handle_ = nullptr;
}

std::string UsbLink::name() const {
  return "board on USB bus " + std::to_string(bus_) + " address " + std::to_string(address_) +
         (serial_.empty() ? "" : " (serial " + serial_ + ")");
}

}  // namespace mark::lmc
