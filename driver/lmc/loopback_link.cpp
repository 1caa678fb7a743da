#include "driver/lmc/loopback_link.hpp"

#include <chrono>
#include <thread>

namespace mark::lmc {

void LoopbackLink::fail(Urb result, const char* what) const {
  switch (result) {
    case Urb::stall: throw LinkError(LinkFailure::stall, std::string("lmc: ") + what + ": endpoint stalled");
    case Urb::no_device: throw LinkError(LinkFailure::no_device, std::string("lmc: ") + what + ": no device");
    default: throw LinkError(LinkFailure::timeout, std::string("lmc: ") + what + ": timed out");
  }
}

void LoopbackLink::write(std::span<const std::uint8_t> bytes) {
  const Urb r = board_.out(bytes);
  if (r == Urb::done) return;
  // libusb waits out its timeout on a URB the device never completes, then discards it.
  if (r == Urb::pending) std::this_thread::sleep_for(std::chrono::duration<double>(timeout_s_));
  fail(r, "write to the emulated board");
}

std::array<std::uint8_t, kReplyBytes> LoopbackLink::read() {
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration<double>(timeout_s_);
  std::array<std::uint8_t, kReplyBytes> reply{};
  for (;;) {
    const Urb r = board_.in(reply);
    if (r == Urb::done) return reply;
    if (r != Urb::pending || Clock::now() >= deadline) fail(r, "read from the emulated board");
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
}

void LoopbackLink::reopen() {
  if (board_.state().unplugged)
    throw LinkError(LinkFailure::no_device, "lmc: the emulated board is unplugged");
}

}  // namespace mark::lmc
