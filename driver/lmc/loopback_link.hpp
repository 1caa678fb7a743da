#pragma once
// Test support: the driver talking straight to an in-process EmulatedBoard, with the link
// semantics of libusb (a URB the board leaves pending times out after the link timeout; a
// stall or a vanished board fails at once) but no USB stack. The umockdev tests put the same
// board behind real usbfs ioctls; these are the fast ones.
#include "driver/lmc/emulated_board.hpp"
#include "driver/lmc/link.hpp"

namespace mark::lmc {

class LoopbackLink : public LmcLink {
 public:
  explicit LoopbackLink(EmulatedBoard& board, double timeout_s = 0.1)
      : board_(board), timeout_s_(timeout_s) {}

  void write(std::span<const std::uint8_t> bytes) override;
  std::array<std::uint8_t, kReplyBytes> read() override;
  void clear_halt() override { board_.clear_halt(); }
  void reopen() override;
  std::string name() const override { return "emulated board (loopback)"; }

 private:
  [[noreturn]] void fail(Urb result, const char* what) const;
  EmulatedBoard& board_;
  double timeout_s_;
};

}  // namespace mark::lmc
