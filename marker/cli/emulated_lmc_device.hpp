#pragma once
// `--device lmc-emulated[:VARIANT]` for a job: the whole LMC path without a board — the plan as
// device commands, the real driver's list packets, the emulated board executing them on its own
// 10 µs clock (in the variant's reading of the board), and its output into the simulated
// scanner, whose quality figures the job then reports like the simulator's. Real time by
// default; `virtual_time` runs the board as fast as it can (never past the data it has).
//
// driver/lmc/ and driver/sim/ know nothing of each other: this is where they meet, and the only
// place (marker/cli/device_factory.cpp opens it with an evaluator of its scanner).
#include <memory>
#include <string>

#include "driver/lmc/emulated_link.hpp"
#include "driver/lmc/lmc_device.hpp"
#include "driver/lmc/lmc_spec.hpp"
#include "driver/sim/sim_scanner.hpp"

namespace mark::cli {

class EmulatedLmcDevice : public CommandDevice {
 public:
  EmulatedLmcDevice(SimScannerOptions scanner, lmc::LmcOptions options, const lmc::LmcSpec& spec, bool virtual_time);
  ~EmulatedLmcDevice() override;

  DeviceDescription describe() const override;
  // The scanner's job begins with the board's: what the board executes from here on is this
  // job's mark. The board's laser is the job's source.
  void begin_job(const JobHeader& header) override;
  void submit(std::span<const DeviceCommand> commands) override { board_->submit(commands); }
  // The board's report, with the scanner's pulse figures added.
  DeviceReport end_job() override;
  void abort() noexcept override { board_->abort(); }
  DeviceStatus status() const override { return board_->status(); }
  void reset() override;

  SimScanner& scanner() { return *scanner_; }
  lmc::LmcDevice& board() { return *board_; }
  // The emulated board itself: tests set its input pins and read the port words it took.
  lmc::EmulatedBoard& emulated_board() { return link_->board(); }

 private:
  std::unique_ptr<SimScanner> scanner_;  // before board_: the board writes into it until it goes
  lmc::EmulatedLink* link_ = nullptr;    // owned by board_
  std::unique_ptr<lmc::LmcDevice> board_;
};

}  // namespace mark::cli
