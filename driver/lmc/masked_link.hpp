#pragma once
// A link that cannot fire the laser: every transfer is read before it goes out, and one that
// would enable the laser — a WritePort (single or in a list) with the laser bit set, a master
// oscillator opened (Fiber_SetMo(1), FiberOpenMO(1)), EnableLaser, LaserSignalOn, a LaserOnPoint
// — is refused with a LinkError and never reaches the board. `marker lmc probe` talks to a board
// through it, so the probe is safe by construction, not by care: the red pointer is the only
// light it can switch on.
#include <cstdint>
#include <string>

#include "driver/lmc/link.hpp"

namespace mark::lmc {

class MaskedLink : public LmcLink {
 public:
  MaskedLink(LmcLink& inner, int laser_bit) : inner_(inner), laser_mask_(std::uint16_t(1u << laser_bit)) {}

  void write(std::span<const std::uint8_t> bytes) override;
  std::array<std::uint8_t, kReplyBytes> read() override { return inner_.read(); }
  void clear_halt() override { inner_.clear_halt(); }
  void reopen() override { inner_.reopen(); }
  void flush() override { inner_.flush(); }
  void remember_serial(const std::string& serial) override { inner_.remember_serial(serial); }
  std::string name() const override { return inner_.name() + " (laser masked off)"; }
  bool simulated_replies() const override { return inner_.simulated_replies(); }

  std::uint64_t refused() const { return refused_; }

 private:
  // Why this word would let light out, or nullptr.
  const char* fires(const Word& w) const;
  LmcLink& inner_;
  std::uint16_t laser_mask_;
  std::uint64_t refused_ = 0;
};

}  // namespace mark::lmc
