#include "driver/lmc/emulated_board.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

namespace mark::lmc {
namespace {

std::string hex(std::uint16_t v) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "0x%04X", v);
  return buf;
}

}  // namespace

namespace {

void shallow(BoardOptions& o) { o.list_capacity = 2; }
const BoardVariant kVariants[] = {
    {"reference", "whole ticks per move, parameter words free, a JumpTo does not wait, polygon delay in µs, "
                  "4 packets, registers 0 at power-on", [](BoardOptions&) {}},
    {"exact_ticks", "moves in their exact time, the fraction of a tick carried",
     [](BoardOptions& o) { o.behaviour.exact_move_time = true; }},
    {"word_ticks", "every word that is not a move takes a tick of its own",
     [](BoardOptions& o) { o.behaviour.word_ticks = true; }},
    {"jump_waits", "a JumpTo after a mark run waits out the laser-off delay",
     [](BoardOptions& o) { o.behaviour.jump_waits_off_delay = true; }},
    {"polygon_10us", "PolygonDelay read in 10 µs units (meerk40t since 2025)",
     [](BoardOptions& o) { o.polygon_delay_unit = PolygonDelayUnit::ten_us; }},
    {"shallow_buffer", "2 packets buffered before READY clears", shallow},
    {"deep_buffer", "16 packets buffered before READY clears", [](BoardOptions& o) { o.list_capacity = 16; }},
    {"foreign_settings", "registers as another program left them (jump delay 500 µs, ...)",
     [](BoardOptions& o) { o.behaviour.foreign_settings = true; }},
    {"slowest", "word ticks, a waiting JumpTo, polygon delay in 10 µs, foreign registers, 2 packets",
     [](BoardOptions& o) {
       o.behaviour.word_ticks = o.behaviour.jump_waits_off_delay = o.behaviour.foreign_settings = true;
       o.polygon_delay_unit = PolygonDelayUnit::ten_us;
       shallow(o);
     }},
};

}  // namespace

std::span<const BoardVariant> board_variants() { return kVariants; }

BoardOptions with_variant(BoardOptions options, std::string_view name) {
  std::string known;
  for (const BoardVariant& v : kVariants) {
    if (v.name == name) {
      v.apply(options);
      return options;
    }
    known += (known.empty() ? "" : ", ") + std::string(v.name);
  }
  throw DeviceError("emulated board: no behaviour variant '" + std::string(name) + "' (known: " + known + ")");
}

EmulatedBoard::EmulatedBoard(BoardOptions options, BoardFaults faults)
    : options_(options),
      faults_(faults),
      units_(options.field_mm, options.axes, options.polygon_delay_unit),
      executor_(units_, options.laser_bit, options.red_bit, options.behaviour) {
  executor_.set_scanner(options_.scanner);
}

EmulatedBoard::~EmulatedBoard() { stop_clock(); }

void EmulatedBoard::violation(std::string what) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "[t=%.5f s] ", double(ticks_) * kTick_s);
  violations_.push_back(buf + what);
}

bool EmulatedBoard::ready_locked() const {
  const double now = double(ticks_) * kTick_s;
  return !unplugged_ && now >= withhold_until_s_ && buffer_.size() < options_.list_capacity;
}

std::uint16_t EmulatedBoard::status_locked() const {
  std::uint16_t s = 0;
  if (ready_locked()) s |= status::ready;
  if (executor_.executing()) s |= status::busy;
  if (executor_.executing() && executor_.paused()) s |= status::paused;
  return s;
}

// ---------------------------------------------------------------------------------------------
// USB side

Urb EmulatedBoard::out(std::span<const std::uint8_t> bytes) {
  std::unique_lock lock(mutex_);
  const double now = double(ticks_) * kTick_s;
  if (unplugged_) return Urb::no_device;
  if (now < hang_until_s_) return Urb::pending;
  if (stalled_) return Urb::stall;
  if (bytes.size() == kCommandBytes) {
    const Word w = load(bytes.data());
    if (const auto fault = single_fault(w)) {
      if (*fault == Urb::no_device) {
        lock.unlock();
        if (on_unplug) on_unplug();
      }
      if (*fault != Urb::done) return *fault;
    }
    // ReadPort is left out of the wire record (counted in read_ports): a station's trigger polls
    // it every millisecond, and the record would grow for as long as the station runs.
    if (w.opcode() != static_cast<std::uint16_t>(Op::ReadPort))
      wire_.push_back(WireRecord{now, false, w, 0, status_locked(), std::chrono::steady_clock::now()});
    on_single(w);
    if (drop_next_reply_) {  // SingleFault::no_answer: taken, never answered
      drop_next_reply_ = false;
      const CommandSpec* spec = find_command(w.opcode());
      if (spec && spec->reply && !replies_.empty()) replies_.pop_back();
    }
    return Urb::done;
  }
  if (bytes.size() != kPacketBytes) {
    violation("a transfer of " + std::to_string(bytes.size()) + " bytes (the board takes 12 or 3072)");
    return Urb::stall;
  }
  const std::size_t number = ++packets_seen_;
  if (faults_.unplug_at_packet == number) {
    unplug_locked();
    lock.unlock();
    if (on_unplug) on_unplug();
    return Urb::no_device;
  }
  if (faults_.hang_at_packet == number) {
    hang_until_s_ = faults_.hang_s > 0 ? now + faults_.hang_s : std::numeric_limits<double>::infinity();
    return Urb::pending;
  }
  if (faults_.stall_at_packet == number) {
    stalled_ = true;
    return Urb::stall;
  }
  wire_.push_back(WireRecord{now, true, {}, number, status_locked(), std::chrono::steady_clock::now()});
  if (!ready_locked()) {
    violation("list packet " + std::to_string(number) + " arrived while READY was clear: lost");
    ++packets_lost_;
    return Urb::done;
  }
  on_packet(bytes);
  if (faults_.withhold_ready_after_packet == number) withhold_until_s_ = now + faults_.withhold_ready_s;
  return Urb::done;
}

Urb EmulatedBoard::in(std::array<std::uint8_t, kReplyBytes>& reply) {
  std::lock_guard lock(mutex_);
  if (unplugged_) return Urb::no_device;
  if (double(ticks_) * kTick_s < hang_until_s_) return Urb::pending;
  if (stalled_) return Urb::stall;
  if (replies_.empty()) return Urb::pending;
  reply = replies_.front();
  replies_.pop_front();
  return Urb::done;
}

void EmulatedBoard::clear_halt() {
  std::lock_guard lock(mutex_);
  stalled_ = false;
}

// faults_.single: what becomes of this command (nullopt: nothing special).
std::optional<Urb> EmulatedBoard::single_fault(const Word& w) {
  if (!faults_.single || w.opcode() != faults_.single->opcode) return std::nullopt;
  if (++single_fault_seen_ != faults_.single->occurrence) return std::nullopt;
  const double now = double(ticks_) * kTick_s;
  switch (faults_.single->kind) {
    case SingleFault::Kind::stall: stalled_ = true; return Urb::stall;
    case SingleFault::Kind::hang: hang_until_s_ = now + faults_.single->hang_s; return Urb::pending;
    case SingleFault::Kind::unplug: unplug_locked(); return Urb::no_device;
    case SingleFault::Kind::no_answer: drop_next_reply_ = true; return Urb::done;
  }
  return std::nullopt;
}

// A word for another kind of source than the board's laser: it would set nothing the laser
// understands (a CO2 power ratio on a fiber's driver, a Q-switch period on a CO2's).
void EmulatedBoard::check_source_word(std::uint16_t op, const std::string& where) {
  const LaserSource src = options_.behaviour.source;
  const bool fiber = src == LaserSource::fiber || src == LaserSource::mopa;
  bool wrong = false;
  switch (static_cast<Op>(op)) {
    case Op::QSwitchPeriod:
    case Op::MarkCurrent:
    case Op::FiberOpenMO: wrong = !fiber; break;
    case Op::FiberYLPMPulseWidth: wrong = src != LaserSource::mopa; break;
    case Op::MarkFreq:
    case Op::MarkPowerRatio:
    case Op::SetCo2Fpk: wrong = fiber; break;
    default: break;
  }
  if (wrong)
    violation(std::string(command_name(op)) + where + " on a board driving a " +
              std::string(to_string(src)) + " source");
}

void EmulatedBoard::on_single(const Word& w) {
  const std::uint16_t op = w.opcode();
  const CommandSpec* spec = find_command(op);
  if (is_list(op)) violation("list command " + hex(op) + " sent alone as a single command");
  else if (!spec) violation("unknown single command " + hex(op));
  Reply r;
  switch (static_cast<Op>(op)) {
    case Op::GetSerialNo:
      r.w = {0, std::uint16_t(options_.serial >> 16), std::uint16_t(options_.serial & 0xFFFF), 0};
      break;
    case Op::GetVersion:
      r.w = {options_.version[0], options_.version[1], options_.version[2], 0};
      break;
    case Op::GetPositionXY: {
      const auto p = executor_.position();
      r.w = {0, p[0], p[1], 0};
      break;
    }
    case Op::ReadPort:
      r.w = {0, inputs_, 0, 0};  // w1, where meerk40t's read_port()[1] reads the pins
      ++read_ports_;
      break;
    case Op::GetMarkTime: {
      const std::uint64_t t = executor_.figures().ticks;
      r.w = {0, std::uint16_t(t >> 16), std::uint16_t(t & 0xFFFF), 0};
      break;
    }
    case Op::ExecuteList:
      executor_.start();
      execute_at_s_ = double(ticks_) * kTick_s;
      break;
    case Op::StopExecute:
    case Op::ResetList:
      executor_.stop();
      buffer_.clear();
      cursor_ = 0;
      break;
    case Op::StopList: executor_.set_paused(true); break;
    case Op::RestartList: executor_.set_paused(false); break;
    case Op::WritePort: executor_.write_port(w.p(1)); break;
    case Op::FiberSetMo: executor_.set_mo(w.p(1) != 0); break;
    case Op::EnableLaser: executor_.set_enabled(laser_enabled_ = true); break;
    case Op::DisableLaser: executor_.set_enabled(laser_enabled_ = false); break;
    case Op::GotoXY:
      if (!executor_.executing()) executor_.goto_xy({w.p(1), w.p(2)});
      break;
    case Op::WriteCorTable:
      cor_table_ = w.p(1);
      cor_open_ = w.p(1) != 0;
      cor_lines_ = 0;
      break;
    case Op::WriteCorLine:
      if (!cor_open_) violation("WriteCorLine without WriteCorTable(1)");
      if (w.p(3) != (cor_lines_ == 0 ? 0 : 1))
        violation("WriteCorLine " + std::to_string(cor_lines_) + " has first-flag " + std::to_string(w.p(3)));
      if (++cor_lines_ > 65 * 65) violation("more than 65 × 65 WriteCorLine");
      break;
    default: break;
  }
  if (spec && !spec->reply) return;
  r.w[3] = status_locked();
  replies_.push_back(encode_reply(r));
}

void EmulatedBoard::on_packet(std::span<const std::uint8_t> bytes) {
  std::vector<Word> words(kCommandsPerPacket);
  bool ended = false;
  const std::size_t number = packets_seen_;
  for (std::size_t i = 0; i < kCommandsPerPacket; ++i) {
    const Word w = load(bytes.data() + i * kCommandBytes);
    words[i] = w;
    const std::uint16_t op = w.opcode();
    const std::string where = " in packet " + std::to_string(number) + " slot " + std::to_string(i);
    if (ended) {
      if (w != word(Op::EndOfList)) violation("a command after EndOfList" + where + ": " + hex(op));
      continue;
    }
    if (!is_list(op)) violation("single command " + hex(op) + where);
    else if (!find_command(op)) violation("unknown list command " + hex(op) + where);
    else check_source_word(op, where);
    if (op == static_cast<std::uint16_t>(Op::EndOfList)) ended = true;
  }
  packets_.push_back(words);
  buffer_.push_back(std::move(words));
}

// ---------------------------------------------------------------------------------------------
// The list feed (the executor reads the buffered packets through it)

const Word* EmulatedBoard::peek() {
  while (!buffer_.empty() && cursor_ >= kCommandsPerPacket) {
    buffer_.pop_front();
    cursor_ = 0;
  }
  return buffer_.empty() ? nullptr : &buffer_.front()[cursor_];
}

void EmulatedBoard::pop() {
  const Word w = buffer_.front()[cursor_++];
  // EndOfList ends the list: the rest of its packet is padding.
  if (w.opcode() == static_cast<std::uint16_t>(Op::EndOfList) || cursor_ >= kCommandsPerPacket) {
    buffer_.pop_front();
    cursor_ = 0;
  }
}

// ---------------------------------------------------------------------------------------------
// Clock

void EmulatedBoard::advance_locked(std::uint64_t ticks) {
  const bool was_finished = executor_.finished();
  try {
    executor_.run(ticks, *this);
  } catch (const std::exception& e) {
    violation(std::string("the scanner refused the board's output: ") + e.what());
    executor_.stop();
  }
  ticks_ += ticks;
  if (!was_finished && executor_.finished()) finished_cv_.notify_all();
}

void EmulatedBoard::advance(double seconds) {
  std::uint64_t ticks = static_cast<std::uint64_t>(std::llround(seconds / kTick_s));
  bool notify = false;
  {
    std::lock_guard lock(mutex_);
    if (faults_.unplug_after_execute_s && execute_at_s_ && !unplugged_) {
      const double at = *execute_at_s_ + *faults_.unplug_after_execute_s;
      const double now = double(ticks_) * kTick_s;
      if (now + double(ticks) * kTick_s >= at) {
        const auto first = static_cast<std::uint64_t>(std::max(0.0, std::ceil((at - now) / kTick_s)));
        advance_locked(std::min(first, ticks));
        ticks -= std::min(first, ticks);
        unplug_locked();
        notify = true;
      }
    }
    advance_locked(ticks);
  }
  if (notify && on_unplug) on_unplug();
}

void EmulatedBoard::start_clock(double time_scale) {
  stop_clock();
  clock_run_ = true;
  clock_ = std::thread([this, time_scale] {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    std::uint64_t done = 0;
    while (clock_run_.load()) {
      std::this_thread::sleep_for(std::chrono::microseconds(500));
      const double elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
      const auto due = static_cast<std::uint64_t>(elapsed * time_scale / kTick_s);
      if (due > done) {
        advance(double(due - done) * kTick_s);
        done = due;
      }
    }
  });
}

void EmulatedBoard::start_virtual_clock() {
  stop_clock();
  clock_run_ = true;
  clock_ = std::thread([this] {
    using Clock = std::chrono::steady_clock;
    auto last = Clock::now();
    while (clock_run_.load()) {
      std::uint64_t ran = 0;
      {
        std::lock_guard lock(mutex_);
        const bool was_finished = executor_.finished();
        try {
          ran = executor_.run(1000, *this, true);
        } catch (const std::exception& e) {
          violation(std::string("the scanner refused the board's output: ") + e.what());
          executor_.stop();
        }
        ticks_ += ran;
        if (!was_finished && executor_.finished()) finished_cv_.notify_all();
        if (ran == 0) {
          // Waiting (for data, for ExecuteList): time passes as on the wall clock, so READY
          // withheld for a while comes back.
          const auto now = Clock::now();
          ticks_ += static_cast<std::uint64_t>(std::chrono::duration<double>(now - last).count() / kTick_s);
        }
      }
      last = Clock::now();
      if (ran == 0) std::this_thread::sleep_for(std::chrono::microseconds(100));
    }
  });
}

void EmulatedBoard::stop_clock() {
  clock_run_ = false;
  if (clock_.joinable()) clock_.join();
}

void EmulatedBoard::set_source(LaserSource source) {
  std::lock_guard lock(mutex_);
  options_.behaviour.source = source;
  executor_.set_source(source);
}

void EmulatedBoard::set_single_fault(const SingleFault& fault) {
  std::lock_guard lock(mutex_);
  faults_.single = fault;
  single_fault_seen_ = 0;
}

void EmulatedBoard::unplug_locked() {
  unplugged_ = true;
  replies_.clear();
}

void EmulatedBoard::unplug() {
  {
    std::lock_guard lock(mutex_);
    if (unplugged_) return;
    unplug_locked();
  }
  if (on_unplug) on_unplug();
}

// ---------------------------------------------------------------------------------------------
// Inspection

void EmulatedBoard::set_inputs(std::uint16_t bits) {
  std::lock_guard lock(mutex_);
  inputs_ = bits;
}

std::uint16_t EmulatedBoard::inputs() const {
  std::lock_guard lock(mutex_);
  return inputs_;
}

std::vector<PortWrite> EmulatedBoard::port_writes() const {
  std::lock_guard lock(mutex_);
  return executor_.port_writes();
}

BoardState EmulatedBoard::state() const {
  std::lock_guard lock(mutex_);
  BoardState s;
  s.port = executor_.port();
  s.laser_emitting = executor_.emitting();
  s.executing = executor_.executing();
  s.paused = executor_.paused();
  s.finished = executor_.finished();
  s.mo_open = executor_.mo_open();
  s.laser_enabled = laser_enabled_;
  s.unplugged = unplugged_;
  s.buffered_packets = buffer_.size();
  s.status = status_locked();
  s.device_time_s = double(ticks_) * kTick_s;
  s.position = executor_.position();
  s.executor = executor_.figures();
  s.packets_received = packets_.size();
  s.packets_lost = packets_lost_;
  s.cor_lines = cor_lines_;
  s.cor_table = cor_table_;
  s.read_ports = read_ports_;
  return s;
}

bool EmulatedBoard::unplugged() const {
  std::lock_guard lock(mutex_);
  return unplugged_;
}

std::vector<WireRecord> EmulatedBoard::wire() const {
  std::lock_guard lock(mutex_);
  return wire_;
}

std::vector<std::vector<Word>> EmulatedBoard::packets() const {
  std::lock_guard lock(mutex_);
  return packets_;
}

std::vector<std::string> EmulatedBoard::violations() const {
  std::lock_guard lock(mutex_);
  return violations_;
}

std::vector<Vec2> EmulatedBoard::red_path() const {
  std::lock_guard lock(mutex_);
  return executor_.red_path();
}

bool EmulatedBoard::wait_finished(double timeout_s) const {
  std::unique_lock lock(mutex_);
  return finished_cv_.wait_for(lock, std::chrono::duration<double>(timeout_s),
                               [this] { return executor_.finished(); });
}

void EmulatedBoard::inspect(const std::function<void()>& f) const {
  std::lock_guard lock(mutex_);
  f();
}

}  // namespace mark::lmc
