#pragma once
// `--device lmc-emulated[:VARIANT]`: a link to an emulated board this link owns, its clock
// running in real time (or virtual time: as fast as it can execute, never past its data), in one
// of the board's behaviour variants (emulated_board.hpp). The driver above it is the real one,
// byte for byte; the board's executed list goes to `BoardOptions::scanner` when one is given
// (the job's simulated scanner, wired in marker/cli/device_factory.cpp).
#include <string>

#include "driver/lmc/emulated_board.hpp"
#include "driver/lmc/loopback_link.hpp"

namespace mark::lmc {

class EmulatedLink : public LmcLink {
 public:
  EmulatedLink(BoardOptions board, std::string variant, bool virtual_clock = false);
  ~EmulatedLink() override;

  void write(std::span<const std::uint8_t> bytes) override { loop_.write(bytes); }
  std::array<std::uint8_t, kReplyBytes> read() override { return loop_.read(); }
  void clear_halt() override { loop_.clear_halt(); }
  void reopen() override { loop_.reopen(); }
  std::string name() const override;

  EmulatedBoard& board() { return board_; }
  const std::string& variant() const { return variant_; }
  bool virtual_clock() const { return virtual_; }

 private:
  EmulatedBoard board_;
  LoopbackLink loop_;
  std::string variant_;
  bool virtual_;
};

}  // namespace mark::lmc
