#pragma once
// The byte pipe to one LMC board: bulk OUT on endpoint 0x02 (12-byte commands, 3072-byte list
// packets) and bulk IN on 0x88 (8-byte replies). Implementations: UsbLink (libusb), CaptureLink
// (writes the bytes to a file, answers READY), LoopbackLink (an in-process emulated board).
// A link never retries: a failed transfer throws LinkError and the session decides.
#include <array>
#include <cstdint>
#include <span>
#include <string>

#include "driver/device_error.hpp"
#include "driver/lmc/codec.hpp"

namespace mark::lmc {

enum class LinkFailure {
  timeout,    // the transfer did not complete within the link's timeout
  stall,      // the endpoint is halted (LIBUSB_ERROR_PIPE)
  no_device,  // the board is gone (unplugged, LIBUSB_ERROR_NO_DEVICE)
  io          // any other transfer error
};

std::string_view to_string(LinkFailure failure);

class LinkError : public DeviceError {
 public:
  LinkError(LinkFailure failure, const std::string& message)
      : DeviceError(message), failure_(failure) {}
  LinkFailure failure() const { return failure_; }

 private:
  LinkFailure failure_;
};

class LmcLink {
 public:
  virtual ~LmcLink() = default;
  // One bulk OUT transfer of exactly 12 or 3072 bytes.
  virtual void write(std::span<const std::uint8_t> bytes) = 0;
  // One bulk IN transfer of 8 bytes.
  virtual std::array<std::uint8_t, kReplyBytes> read() = 0;
  // After a stall: clear the halt on both endpoints so a laser-off command can get through.
  // Throws LinkError if that fails too.
  virtual void clear_halt() {}
  // After the link failed (e.g. the board was unplugged and plugged in again): find the same
  // board again and reopen it. Throws LinkError if it is not there.
  virtual void reopen() {}
  // Writes out whatever the link buffers (a capture file); throws DeviceError if it cannot.
  virtual void flush() {}
  // The board answered GetSerialNo with this: a link that can reopen uses it to find the same
  // board again.
  virtual void remember_serial(const std::string& /*serial*/) {}
  // "usb 1-2 (bus 1, address 2)", "capture out.lmc", ...
  virtual std::string name() const = 0;
  // Whether status replies come from a real (or emulated) board. A capture answers READY and
  // not BUSY without a board behind it.
  virtual bool simulated_replies() const { return false; }
};

}  // namespace mark::lmc
