#pragma once
// Opening the board a device name (lmc_spec.hpp) names: a USB board, a capture file, or the
// emulated board.
#include <memory>

#include "driver/lmc/emulated_link.hpp"
#include "driver/lmc/lmc_device.hpp"
#include "driver/lmc/lmc_spec.hpp"

namespace mark::lmc {

// How an emulated board is run: its clock, and where its executed list goes (nullptr: nowhere).
struct EmulatedSetup {
  bool virtual_clock = false;
  Sink<ScanSample>* scanner = nullptr;
};

// The emulated board for a host set up with `options`: the same lens, wiring and port bits
// (what it decodes its words with); how it reads what the references leave open comes from its
// variant, not from the host.
BoardOptions emulated_board_options(const LmcOptions& options);

// Opens the board (or the capture file, or the emulated board) and runs the init sequence.
std::unique_ptr<LmcDevice> open_lmc(const LmcSpec& spec, LmcOptions options, const EmulatedSetup& emulated = {});

// The link alone, for what talks to a board below the device (`marker lmc probe`).
std::unique_ptr<LmcLink> open_lmc_link(const LmcSpec& spec, const LmcOptions& options, const EmulatedSetup& emulated = {});

}  // namespace mark::lmc
