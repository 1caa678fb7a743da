#include "marker/cli/emulated_lmc_device.hpp"

#include "driver/lmc/lmc_open.hpp"

namespace mark::cli {

EmulatedLmcDevice::EmulatedLmcDevice(SimScannerOptions scanner, lmc::LmcOptions options, const lmc::LmcSpec& spec,
                                     bool virtual_time) {
  // The board's clock is the scanner's tick.
  scanner.tick_s = 10e-6;
  // The board's output carries the light's power (its MarkCurrent), the pen's power in it.
  scanner.light_power = true;
  scanner_ = std::make_unique<SimScanner>(std::move(scanner));
  auto link = lmc::open_lmc_link(spec, options, lmc::EmulatedSetup{virtual_time, scanner_.get()});
  link_ = static_cast<lmc::EmulatedLink*>(link.get());
  board_ = std::make_unique<lmc::LmcDevice>(std::move(link), std::move(options));
}

EmulatedLmcDevice::~EmulatedLmcDevice() {
  board_.reset();  // stops the board's clock before the scanner goes
}

DeviceDescription EmulatedLmcDevice::describe() const {
  DeviceDescription d = board_->describe();
  d.name = "lmc-emulated:" + link_->variant() + " (" + d.name + ", " +
           (link_->virtual_clock() ? "virtual time" : "real time") + ", simulated " + scanner_->options().head.name + ")";
  return d;
}

void EmulatedLmcDevice::begin_job(const JobHeader& header) {
  if (!header.pens.empty()) link_->board().set_source(header.pens.front().laser.source);
  if (scanner_->status().state != DeviceState::idle) scanner_->reset();
  scanner_->begin_job(header);
  board_->begin_job(header);
}

DeviceReport EmulatedLmcDevice::end_job() {
  DeviceReport r = board_->end_job();
  // The board has stopped (done: not BUSY; aborted or failed: its stop sequence): what it
  // executed is in the scanner.
  const DeviceReport s = scanner_->end_job();
  for (const auto& [key, value] : s.figures)
    if (key.starts_with("pulse")) r.figures.emplace_back(key, value);
  r.figures.emplace_back("scanner_device_time_s", s.device_time_s);
  // What a real board does not tell the host: how often it ran out of list data mid-job and
  // held the mirrors, gate closed (a mark run broken there, a timed move's pre-compensation
  // thrown off).
  const lmc::ExecutorFigures& x = link_->board().state().executor;
  r.figures.emplace_back("board_underrun_events", static_cast<double>(x.underrun_events));
  r.figures.emplace_back("board_underrun_s", static_cast<double>(x.underrun_ticks) * 10e-6);
  return r;
}

void EmulatedLmcDevice::reset() {
  board_->reset();
  scanner_->reset();
}

}  // namespace mark::cli
