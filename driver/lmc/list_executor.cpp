#include "driver/lmc/list_executor.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace mark::lmc {
namespace {
std::uint64_t ticks_of(double seconds) {
  return seconds > 0 ? static_cast<std::uint64_t>(std::llround(seconds / kTick_s)) : 0;
}
}  // namespace

ListExecutor::ListExecutor(const FieldUnits& units, int laser_bit, int red_bit, ExecutorBehaviour behaviour)
    : units_(units), laser_bit_(laser_bit), red_bit_(red_bit), behaviour_(behaviour) {
  if (behaviour_.foreign_settings) {
    // What a board left by another program might hold (ExecutorBehaviour::foreign_settings).
    jump_speed_ = 2000, mark_speed_ = 300;
    on_delay_s_ = 200e-6, off_delay_s_ = 250e-6, jump_delay_s_ = 500e-6;
    polygon_s_ = decode_polygon_delay(500, 0, units_.polygon_unit());
    power_ = 0x800;
    mark_period_ = 500, power_ratio_ = 500;  // 20 kHz, half the period high
    figures_.frequency_khz = 20;
  }
  update_power();
}

void ListExecutor::set_port(std::uint16_t bits, bool list) {
  port_ = bits;
  port_writes_.push_back({bits, list});
}

void ListExecutor::update_power() {
  if (limits_of(behaviour_.source).master_oscillator) {
    light_power_ = std::min<std::uint16_t>(power_, 0xFFF) / 4095.0;
  } else {
    // The PWM's high time (50 ns) over its period (100 ns): the duty.
    light_power_ = mark_period_ ? std::min(1.0, power_ratio_ / (2.0 * mark_period_)) : 0.0;
  }
  figures_.power_fraction = light_power_;
}

void ListExecutor::set_laser_word(const Word& w) {
  switch (static_cast<Op>(w.opcode())) {
    case Op::QSwitchPeriod:
      if (w.p(1)) figures_.frequency_khz = 20000.0 / w.p(1);
      break;
    case Op::MarkCurrent: power_ = w.p(1); break;
    case Op::MarkFreq:
      mark_period_ = w.p(1);
      if (w.p(1)) figures_.frequency_khz = 10000.0 / w.p(1);
      break;
    case Op::MarkPowerRatio: power_ratio_ = w.p(1); break;
    case Op::FiberYLPMPulseWidth: figures_.pulse_width_ns = w.p(1); break;
    default: break;  // SetCo2FPK: no effect on where the light goes or how much
  }
  update_power();
}

std::array<std::uint16_t, 2> ListExecutor::position() const {
  return {static_cast<std::uint16_t>(std::lround(pos_out_[0])),
          static_cast<std::uint16_t>(std::lround(pos_out_[1]))};
}

void ListExecutor::start() {
  if (executing_) return;
  executing_ = true;
  finished_ = ending_ = in_underrun_ = false;
  lit_seen_ = false;
  figures_.lit_stream_hash = 0xcbf29ce484222325ull;  // FNV-1a offset basis
  move_carry_ = 0;
}

void ListExecutor::stop() {
  acts_.clear();
  pos_ = pos_out_;  // the rest of the move is abandoned where the mirrors are
  run_ = false;
  on_countdown_ = off_tail_ = 0;
  executing_ = paused_ = finished_ = ending_ = in_underrun_ = false;
  emitting_ = false;
}

void ListExecutor::end_run() {
  if (!run_) return;
  run_ = false;
  on_countdown_ = 0;
  off_tail_ = ticks_of(off_delay_s_);
}

void ListExecutor::hold(double seconds, bool forced_gate) { hold_ticks(ticks_of(seconds), forced_gate); }

void ListExecutor::hold_ticks(std::uint64_t n, bool forced_gate) {
  if (n == 0) return;
  Activity a;
  a.n = n;
  a.forced_gate = forced_gate;
  acts_.push_back(a);
}

void ListExecutor::begin_move(const Word& w, bool mark) {
  const std::array<double, 2> to{double(w.p(1)), double(w.p(2))};
  const double dx = to[0] - pos_[0], dy = to[1] - pos_[1];
  const double dist = std::sqrt(dx * dx + dy * dy);
  if (w.p(4) != 0xFFFF && std::abs(double(w.p(4)) - std::floor(dist)) > 1)
    ++figures_.distance_mismatches;
  ++figures_.moves;
  if (port_ & (1u << red_bit_)) {
    const auto mm = [&](std::array<double, 2> u) {
      const auto p = units_.field_point(static_cast<std::uint16_t>(std::lround(u[0])),
                                        static_cast<std::uint16_t>(std::lround(u[1])));
      return Vec2{p[0], p[1]};
    };
    if (red_path_.empty()) red_path_.push_back(mm(pos_));
    red_path_.push_back(mm(to));
  }
  if (mark && dist > 0) {
    const std::array<double, 2> dir{dx / dist, dy / dist};
    if (!run_) {
      run_ = true;
      on_countdown_ = ticks_of(on_delay_s_);
      if (on_delay_s_ < 0) hold(-on_delay_s_, false);  // gate already open: the run is lit
    } else {
      const double cos_phi = std::clamp(dir[0] * run_dir_[0] + dir[1] * run_dir_[1], -1.0, 1.0);
      hold(polygon_s_ * (1 - cos_phi), false);
    }
    run_dir_ = dir;
  } else if (mark) {
    if (!run_) {
      run_ = true;
      on_countdown_ = ticks_of(on_delay_s_);
    }
  }
  if (dist == 0) return;
  const double step = std::max<std::uint16_t>(mark ? mark_speed_ : jump_speed_, 1) / 100.0;
  Activity a;
  a.move = true;
  a.from = pos_;
  a.to = to;
  if (behaviour_.exact_move_time) {
    const double t = move_carry_ + dist / step;
    a.n = static_cast<std::uint64_t>(std::floor(t + 1e-9));
    move_carry_ = std::max(0.0, t - double(a.n));
  } else {
    a.n = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::ceil(dist / step - 1e-9)));
  }
  pos_ = to;  // where the list leaves the mirrors; the output interpolates towards it
  if (a.n == 0) {
    pos_out_ = to;  // less than a tick, carried: the mirrors are there by the next tick
    return;
  }
  acts_.push_back(a);
}

bool ListExecutor::fetch(ListFeed& feed) {
  while (acts_.empty() && !ending_) {
    const Word* next = feed.peek();
    if (!next) return false;
    const Word w = *next;
    feed.pop();
    ++figures_.executed;
    const Op op = static_cast<Op>(w.opcode());
    if (behaviour_.word_ticks && op != Op::JumpTo && op != Op::MarkTo && op != Op::EndOfList)
      hold_ticks(1, false);
    switch (op) {
      case Op::JumpTo:
        end_run();
        if (behaviour_.jump_waits_off_delay) hold_ticks(off_tail_, false);  // gate open: the off delay
        begin_move(w, false);
        hold(jump_delay_s_, false);
        break;
      case Op::MarkTo: begin_move(w, true); break;
      case Op::DelayTime:
        end_run();
        hold(w.p(1) * kTick_s, false);
        break;
      case Op::LaserOnPoint:
        end_run();
        hold(w.p(1) * kTick_s, true);
        break;
      case Op::EndOfList:
        end_run();
        ending_ = true;
        break;
      case Op::ReadyMark: end_run(); break;
      case Op::JumpSpeed: jump_speed_ = w.p(1); break;
      case Op::MarkSpeed: mark_speed_ = w.p(1); break;
      case Op::LaserOnDelay: on_delay_s_ = decode_signed_us(w.p(1), w.p(2)); break;
      case Op::LaserOffDelay:
        off_delay_s_ = decode_signed_us(w.p(1), w.p(2));
        if (off_delay_s_ < 0) {
          ++figures_.unsupported;
          off_delay_s_ = 0;
        }
        break;
      case Op::JumpDelay: jump_delay_s_ = std::max(0.0, decode_signed_us(w.p(1), w.p(2))); break;
      case Op::PolygonDelay:
        polygon_s_ = std::max(0.0, decode_polygon_delay(w.p(1), w.p(2), units_.polygon_unit()));
        break;
      case Op::ListWritePort: set_port(w.p(1), true); break;
      case Op::FiberOpenMO: mo_ = w.p(1) != 0; break;
      case Op::MarkCurrent:
      case Op::QSwitchPeriod:
      case Op::FiberYLPMPulseWidth:
      case Op::MarkFreq:
      case Op::MarkPowerRatio:
      case Op::SetCo2Fpk: set_laser_word(w); break;
      default: ++figures_.unsupported; break;
    }
  }
  return true;
}

ScanSample ListExecutor::sample(bool light) const {
  const auto p = units_.field_point(static_cast<std::uint16_t>(std::lround(pos_out_[0])),
                                    static_cast<std::uint16_t>(std::lround(pos_out_[1])));
  const double h = units_.half_field_mm();
  ScanSample s;
  s.x_mm = static_cast<float>(std::clamp(p[0], -h, h));
  s.y_mm = static_cast<float>(std::clamp(p[1], -h, h));
  s.laser = light;
  s.power = static_cast<std::uint8_t>(std::lround(light_power_ * 255.0));
  return s;
}

void ListExecutor::tick(std::vector<ScanSample>& out) {
  Activity& a = acts_.front();
  const bool gate = (run_ && on_countdown_ == 0) || off_tail_ > 0 || a.forced_gate;
  ++a.k;
  if (a.move) {
    const double f = double(a.k) / double(a.n);
    pos_out_ = {a.from[0] + (a.to[0] - a.from[0]) * f, a.from[1] + (a.to[1] - a.from[1]) * f};
  }
  emit(gate, out);
  if (run_ && on_countdown_ > 0) --on_countdown_;
  if (off_tail_ > 0) --off_tail_;
  if (a.k >= a.n) acts_.pop_front();
}

void ListExecutor::emit(bool gate, std::vector<ScanSample>& out) {
  // A fiber needs its master oscillator open; CO2 and UV sources have none.
  const bool oscillator = mo_ || !limits_of(behaviour_.source).master_oscillator;
  emitting_ = gate && (port_ & (1u << laser_bit_)) && enabled_ && oscillator;
  ++figures_.ticks;
  if (emitting_) ++figures_.lit_ticks;
  out.push_back(sample(emitting_));
  lit_seen_ = lit_seen_ || emitting_;
  if (lit_seen_) {
    const ScanSample& s = out.back();
    std::uint8_t b[10];
    std::memcpy(b, &s.x_mm, 4);
    std::memcpy(b + 4, &s.y_mm, 4);
    b[8] = s.laser, b[9] = s.power;
    std::uint64_t h = figures_.lit_stream_hash;
    for (std::uint8_t c : b) h = (h ^ c) * 0x100000001b3ull;
    figures_.lit_stream_hash = h;
  }
}

std::uint64_t ListExecutor::run(std::uint64_t ticks, ListFeed& feed, bool stop_at_underrun) {
  if (!executing_ || paused_) {
    emitting_ = false;
    return 0;
  }
  std::uint64_t ran = 0;
  std::vector<ScanSample> out;
  out.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(ticks, 1u << 16)));
  for (; ran < ticks && executing_; ++ran) {
    if (acts_.empty() && !ending_) {
      if (!fetch(feed) && stop_at_underrun) break;
      if (acts_.empty() && !ending_) {
        // Underrun: the mirrors hold, the gate closes (a stroke is not left burning).
        if (!in_underrun_) {
          ++figures_.underrun_events;
          in_underrun_ = true;
          run_ = false;
          off_tail_ = on_countdown_ = 0;
        }
        ++figures_.underrun_ticks;
        emit(false, out);
        continue;
      }
      in_underrun_ = false;
    }
    if (acts_.empty()) {  // ending: let the laser-off delay run out, then the list is done
      if (off_tail_ > 0) {
        emit(true, out);
        --off_tail_;
        continue;
      }
      executing_ = false;
      finished_ = true;
      emitting_ = false;
      break;
    }
    tick(out);
  }
  if (scanner_ && !out.empty()) scanner_->write(out);
  return ran;
}

}  // namespace mark::lmc
