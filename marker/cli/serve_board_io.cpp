#include "marker/cli/serve_board_io.hpp"

#include <cstdio>
#include <utility>

#include "base/error.hpp"
#include "driver/lmc/lmc_device.hpp"
#include "marker/cli/emulated_lmc_device.hpp"

namespace mark::cli {

namespace {

lmc::LmcDevice* lmc_board(Device& device) {
  if (auto* board = dynamic_cast<lmc::LmcDevice*>(&device)) return board;
  if (auto* emulated = dynamic_cast<EmulatedLmcDevice*>(&device)) return &emulated->board();
  return nullptr;
}

}  // namespace

std::optional<BoardIoOptions> parse_board_io(const BoardIoArgs& args) {
  if (args.trigger.empty() && args.signal.empty()) return std::nullopt;
  BoardIoOptions o;
  if (!args.trigger.empty()) o.trigger_bit = parse_board_trigger(args.trigger, "--trigger");
  if (!args.signal.empty()) o.signals = parse_board_signals(args.signal, "--signal");
  o.debounce_s = args.debounce_ms / 1000;
  o.min_pulse_s = args.min_pulse_ms / 1000;
  return o;
}

std::unique_ptr<BoardIo> open_board_io(Station& station, Device& device, const BoardIoOptions& o,
                                       std::function<void(const std::string&)> log) {
  lmc::LmcDevice* board = lmc_board(device);
  if (!board)
    throw InputError(std::string(o.trigger_bit ? "--trigger" : "--signal") +
                     ": the board's pins need --device lmc or lmc-emulated (the station's device is \"" +
                     device.describe().name + "\")");
  const std::uint16_t clash = o.signals.mask() & board->reserved_port_bits();
  if (clash) {
    int b = 0;
    while (!(clash & (1u << b))) ++b;
    throw InputError("--signal: output bit " + std::to_string(b) + " is the board's " +
                     (b == board->options().laser_port_bit ? "laser enable" : "red pointer") +
                     " bit (use another: the laser and red-pointer bits are the driver's alone)");
  }
  BoardPort port;
  port.read_inputs = [board] { return board->read_inputs(); };
  port.set_outputs = [board](std::uint16_t bits) { board->set_signal_bits(bits); };
  port.write_outputs = [board] { return board->write_outputs(); };
  if (log) {
    char line[240];
    std::snprintf(line, sizeof line, "board I/O on %s:", device.describe().name.c_str());
    std::string text = line;
    if (o.trigger_bit) {
      std::snprintf(line, sizeof line,
                    " trigger input %d (debounce %g ms, min pulse %g ms; polled every %g ms, %g ms while marking)",
                    *o.trigger_bit, 1e3 * o.debounce_s, 1e3 * o.min_pulse_s, 1e3 * o.poll_idle_s,
                    1e3 * o.poll_marking_s);
      text += line;
    }
    const std::pair<const char*, const std::optional<int>*> named[] = {
        {"ready", &o.signals.ready}, {"busy", &o.signals.busy}, {"done", &o.signals.done}, {"error", &o.signals.error}};
    for (const auto& [name, b] : named)
      if (*b) text += std::string(" ") + name + "=output " + std::to_string(**b);
    log(text);
  }
  return std::make_unique<BoardIo>(station, std::move(port), o, std::move(log));
}

}  // namespace mark::cli
