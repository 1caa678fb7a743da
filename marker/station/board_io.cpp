#include "marker/station/board_io.hpp"

#include <chrono>

#include "base/error.hpp"

namespace mark {

namespace {

using SteadyClock = std::chrono::steady_clock;

SteadyClock::duration after(double seconds) {
  return std::chrono::duration_cast<SteadyClock::duration>(std::chrono::duration<double>(seconds));
}

constexpr double kWriteRetry_s = 0.1;  // outputs the board did not take: tried again after this
// Times compare with this slack: a sample due exactly at the debounce must not miss it by a
// rounding error.
constexpr double kSlack_s = 1e-9;

// A pin number 0–15 from `text` (digits only), or nothing.
std::optional<int> pin(std::string_view text) {
  if (text.empty() || text.size() > 2) return std::nullopt;
  int n = 0;
  for (const char c : text) {
    if (c < '0' || c > '9') return std::nullopt;
    n = n * 10 + (c - '0');
  }
  return n <= 15 ? std::optional(n) : std::nullopt;
}

// The text as it may go in a one-line message: printable ASCII only, at most 40 characters.
std::string shown(std::string_view text) {
  std::string s;
  for (const char c : text.substr(0, 40)) s += (c >= 0x20 && c < 0x7F) ? c : '?';
  if (text.size() > 40) s += "...";
  return s;
}

std::uint16_t bit(const std::optional<int>& b) { return b ? static_cast<std::uint16_t>(1u << *b) : 0; }

}  // namespace

std::uint16_t BoardSignals::mask() const { return bit(ready) | bit(busy) | bit(done) | bit(error); }

std::uint16_t BoardSignals::word(const StationLights& l) const {
  return static_cast<std::uint16_t>((l.ready ? bit(ready) : 0) | (l.busy ? bit(busy) : 0) |
                                    (l.done ? bit(done) : 0) | (l.error ? bit(error) : 0));
}

int parse_board_trigger(std::string_view text, std::string_view option) {
  constexpr std::string_view kind = "lmc-input:";
  if (text.substr(0, kind.size()) != kind)
    throw InputError(std::string(option) + ": \"" + shown(text) +
                     "\" is not a trigger (allowed: lmc-input:BIT, BIT 0 to 15: an input pin of the LMC board)");
  const auto b = pin(text.substr(kind.size()));
  if (!b)
    throw InputError(std::string(option) + ": \"" + shown(text) + "\": the input bit must be 0 to 15");
  return *b;
}

BoardSignals parse_board_signals(std::string_view text, std::string_view option) {
  const std::string where(option);
  if (text.empty()) throw InputError(where + ": empty (allowed: ready=BIT,busy=BIT,done=BIT,error=BIT, any of them)");
  BoardSignals s;
  std::uint16_t used = 0;
  std::size_t at = 0;
  while (at <= text.size()) {
    const std::size_t comma = std::min(text.find(',', at), text.size());
    const std::string_view item = text.substr(at, comma - at);
    const std::size_t eq = item.find('=');
    const std::string_view name = item.substr(0, eq);
    std::optional<int>* slot = name == "ready" ? &s.ready
                               : name == "busy" ? &s.busy
                               : name == "done" ? &s.done
                               : name == "error" ? &s.error
                                                 : nullptr;
    if (!slot || eq == std::string_view::npos)
      throw InputError(where + ": \"" + shown(item) + "\" is not a signal (allowed: ready=BIT, busy=BIT, done=BIT, error=BIT)");
    if (*slot) throw InputError(where + ": " + std::string(name) + " is given twice");
    const auto b = pin(item.substr(eq + 1));
    if (!b) throw InputError(where + ": \"" + shown(item) + "\": the output bit must be 0 to 15");
    if (used & bit(b)) throw InputError(where + ": output bit " + std::to_string(*b) + " is given to two signals");
    used |= bit(b);
    *slot = b;
    at = comma + 1;
  }
  return s;
}

bool TriggerFilter::sample(bool high, double t_s) {
  if (!primed_) {
    // The pin as found: no edge, and a pin already high has to fall first.
    primed_ = true;
    candidate_ = stable_ = high;
    candidate_since_s_ = stable_since_s_ = t_s;
    fired_ = true;
    return false;
  }
  if (high != candidate_) {
    candidate_ = high;
    candidate_since_s_ = t_s;
  }
  if (candidate_ != stable_ && t_s - candidate_since_s_ + kSlack_s >= debounce_s_) {
    stable_ = candidate_;
    stable_since_s_ = candidate_since_s_;  // the level changed when the pin last went there
    if (stable_) fired_ = false;           // a new pulse
  }
  // The pin itself high too: a pin that just fell is still high debounced, but its pulse ended.
  if (stable_ && candidate_ && !fired_ && t_s - stable_since_s_ + kSlack_s >= min_pulse_s_) {
    fired_ = true;
    return true;
  }
  return false;
}

BoardIo::BoardIo(Station& station, BoardPort port, BoardIoOptions options,
                 std::function<void(const std::string&)> log)
    : station_(station), port_(std::move(port)), options_(options), log_(std::move(log)),
      shared_(std::make_shared<Shared>()) {
  shared_->signals = options_.signals;
  shared_->set_outputs = port_.set_outputs;
  // The listener first, then the state as it is: an event in between is applied after it.
  station_.add_listener([shared = shared_](const StationEvent& e) { on_event(*shared, e); });
  {
    const StationStatus now = station_.status();
    std::lock_guard lock(shared_->mutex);
    shared_->state = now.state;
    shared_->last = now.last;
    shared_->set_outputs(shared_->signals.word(station_lights(now.state, now.last)));
    shared_->outputs_dirty = true;
  }
  if (!flush_outputs()) {
    std::lock_guard lock(shared_->mutex);
    shared_->outputs_dirty = true;
  }
  poller_ = std::thread([this] { run(); });
}

BoardIo::~BoardIo() { stop(); }

void BoardIo::stop() {
  {
    std::lock_guard lock(shared_->mutex);
    shared_->detached = true;
  }
  shared_->wake.notify_all();
  if (poller_.joinable()) poller_.join();
}

void BoardIo::emit(const std::string& line) const {
  if (log_) log_(line);
}

void BoardIo::on_event(Shared& s, const StationEvent& e) {
  std::lock_guard lock(s.mutex);
  if (s.detached) return;
  if (e.part) s.last = e.part;
  s.state = e.state;
  // Into the device's port word now (no I/O): a part's first WritePort carries busy even when
  // the poller has not written it yet.
  s.set_outputs(s.signals.word(station_lights(s.state, s.last)));
  s.outputs_dirty = true;
  s.wake.notify_all();
}

bool BoardIo::flush_outputs() {
  try {
    port_.write_outputs();  // false: a job runs, and its own port words carry the bits
    if (write_failing_) emit("board outputs: written again");
    write_failing_ = false;
    return true;
  } catch (const std::exception& e) {
    if (!write_failing_) emit(std::string("board outputs: not written: ") + e.what());
    write_failing_ = true;
    return false;
  }
}

void BoardIo::poll_input(TriggerFilter& filter, double t_s) {
  std::uint16_t word = 0;
  try {
    word = port_.read_inputs();
  } catch (const std::exception& e) {
    // No sample: the filter keeps what it had (an abort in progress makes the board refuse
    // everything but its stop sequence for a moment; a board that stopped answering, longer).
    if (!read_failing_) emit(std::string("board input: not read: ") + e.what());
    read_failing_ = true;
    return;
  }
  if (read_failing_) emit("board input: read again");
  read_failing_ = false;
  if (!filter.sample(((word >> *options_.trigger_bit) & 1u) != 0, t_s)) return;
  const std::string input = "input " + std::to_string(*options_.trigger_bit);
  if (const auto refused = station_.mark_async()) {
    ++ignored_;
    emit("trigger ignored: " + refused->code + " (" + input + " rose)");
  } else {
    ++triggers_;
    emit("trigger: " + input + " rose: mark");
  }
}

void BoardIo::run() {
  const auto t0 = SteadyClock::now();
  TriggerFilter filter(options_.debounce_s, options_.min_pulse_s);
  auto next_poll = t0;
  auto next_write = t0;
  for (;;) {
    bool write = false;
    {
      std::unique_lock lock(shared_->mutex);
      const auto due = [&] {
        return shared_->detached || (shared_->outputs_dirty && SteadyClock::now() >= next_write);
      };
      if (options_.trigger_bit) shared_->wake.wait_until(lock, std::min(next_poll, shared_->outputs_dirty ? next_write : next_poll), due);
      else if (shared_->outputs_dirty) shared_->wake.wait_until(lock, next_write, due);
      else shared_->wake.wait(lock, due);
      if (shared_->detached) return;
      if (shared_->outputs_dirty && SteadyClock::now() >= next_write) {
        shared_->outputs_dirty = false;
        write = true;
      }
    }
    if (write && !flush_outputs()) {
      std::lock_guard lock(shared_->mutex);
      shared_->outputs_dirty = true;
      next_write = SteadyClock::now() + after(kWriteRetry_s);
    }
    const auto now = SteadyClock::now();
    if (!options_.trigger_bit || now < next_poll) continue;
    poll_input(filter, std::chrono::duration<double>(now - t0).count());
    bool marking = false;
    {
      std::lock_guard lock(shared_->mutex);
      marking = shared_->state == StationState::marking;
    }
    const double period = marking ? options_.poll_marking_s : options_.poll_idle_s;
    next_poll = now + after(period);
  }
}

}  // namespace mark
