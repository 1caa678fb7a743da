#include "driver/lmc/job_encoder.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace mark::lmc {
namespace {

// The hot path below builds words directly with the unit encoders; these pin its parameter
// layout to the table, so the table stays the one description of the wire.
constexpr bool layout(Op op, std::initializer_list<Unit> units) {
  const CommandSpec& s = spec_of(op);
  std::size_t i = 0;
  for (Unit u : units)
    if (i >= s.count || s.params[i++].unit != u) return false;
  return i == s.count;
}
static_assert(layout(Op::JumpTo, {Unit::x, Unit::y, Unit::word, Unit::distance}));
static_assert(layout(Op::MarkTo, {Unit::x, Unit::y, Unit::word, Unit::distance}));
static_assert(layout(Op::JumpSpeed, {Unit::speed}) && layout(Op::MarkSpeed, {Unit::speed}));
static_assert(layout(Op::LaserOnDelay, {Unit::signed_us}) &&
              layout(Op::LaserOffDelay, {Unit::signed_us}) &&
              layout(Op::JumpDelay, {Unit::signed_us}));
static_assert(layout(Op::PolygonDelay, {Unit::polygon_delay}));
static_assert(layout(Op::DelayTime, {Unit::time_10us}) && layout(Op::LaserOnPoint, {Unit::dwell_10us}));
static_assert(layout(Op::QSwitchPeriod, {Unit::period_50ns}) &&
              layout(Op::MarkCurrent, {Unit::power_12bit}) &&
              layout(Op::FiberYLPMPulseWidth, {Unit::pulse_width_ns}));
static_assert(layout(Op::MarkFreq, {Unit::period_100ns}) &&
              layout(Op::SetCo2Fpk, {Unit::word, Unit::word}) &&
              layout(Op::MarkPowerRatio, {Unit::word}));
static_assert(layout(Op::ListWritePort, {Unit::port}) && layout(Op::ReadyMark, {}) &&
              layout(Op::EndOfList, {}));

constexpr std::uint32_t kMaxDelayTicks = 0xFFFF;   // DelayTime
constexpr std::uint32_t kMaxDwellTicks = 60000;    // LaserOnPoint (galvo.md §1.4)

std::string pen_name(std::size_t i, const char* what) {
  return "pen " + std::to_string(i) + ": " + what;
}

double signed_s(std::array<std::uint16_t, 2> d) { return decode_signed_us(d[0], d[1]); }

}  // namespace

BoardPen encode_pen(const DevicePen& p, std::size_t i, const FieldUnits& u) {
  check_laser_settings(p.laser, "lmc: pen " + std::to_string(i) + ": ");
  BoardPen b;
  b.source = p.laser.source;
  b.jump_speed = encode_speed(p.jump_speed_mm_s, u, pen_name(i, "jump speed"));
  b.mark_speed = encode_speed(p.mark_speed_mm_s, u, pen_name(i, "mark speed"));
  b.laser_on_delay = encode_signed_us(p.laser_on_delay_s, pen_name(i, "laser-on delay"));
  b.laser_off_delay = encode_signed_us(p.laser_off_delay_s, pen_name(i, "laser-off delay"));
  b.jump_delay = encode_signed_us(p.jump_delay_s, pen_name(i, "jump delay"));
  b.polygon_delay = encode_polygon_delay(p.polygon_delay_s, u.polygon_unit());
  b.mark_delay_10us = encode_time_10us(p.mark_delay_s, kMaxDelayTicks, pen_name(i, "mark delay"));
  switch (p.laser.source) {
    case LaserSource::fiber:
    case LaserSource::mopa:
      b.qswitch_period = encode_period_50ns(p.laser.frequency_khz);
      b.power = encode_power_12bit(p.laser.power_pct);
      if (p.laser.source == LaserSource::mopa && p.laser.pulse_width_ns > 0)
        b.pulse_width = encode_pulse_width_ns(p.laser.pulse_width_ns);
      break;
    case LaserSource::co2:
    case LaserSource::uv:
      b.mark_period = encode_period_100ns(p.laser.frequency_khz);
      b.fpk = encode_co2_fpk(p.laser.frequency_khz);
      b.power_ratio = encode_power_ratio(p.laser.power_pct, p.laser.frequency_khz);
      break;
  }
  return b;
}

JobEncoder::JobEncoder(const FieldUnits& units, PacketSink sink)
    : units_(units), sink_(std::move(sink)) {}

void JobEncoder::emit_packet(const PacketInfo& info) {
  sink_(packet_, info);
  ++figures_.packets;
  figures_.list_commands += packet_.used();
  figures_.estimated_s += packet_estimate_s_;
  packet_.clear();
  packet_estimate_s_ = packet_unverified_s_ = 0;
}

void JobEncoder::flush_full() {
  // Commands before the one being encoded are complete; its own words may straddle.
  emit_packet(PacketInfo{current_, packet_estimate_s_, false, packet_estimate_s_ + packet_unverified_s_});
}

void JobEncoder::start_list(double open_mo_delay_s, std::uint16_t port_bits) {
  // Whatever a failed or aborted list left unsent is dropped here: it must never reach the
  // board as part of the next list.
  packet_.clear();
  packet_estimate_s_ = packet_unverified_s_ = 0;
  // Nothing of what an earlier list set is assumed (see the top of the header).
  jump_speed_ = mark_speed_ = kUnknown;
  qswitch_.reset(), power_.reset(), pulse_width_.reset();
  mark_period_.reset(), fpk_.reset(), power_ratio_.reset();
  on_delay_.reset(), off_delay_.reset(), polygon_.reset(), jump_delay_.reset();
  jump_delay_s_ = polygon_s_ = polygon_worst_s_ = 0;
  in_run_ = false;
  timed_ = false;
  tick_debt_ = 0;
  pen_ = nullptr;
  push(word(Op::ReadyMark));
  if (open_mo_delay_s > 0) {
    const std::uint16_t t = encode_time_10us(open_mo_delay_s, kMaxDelayTicks, "open-MO delay");
    push(word(Op::DelayTime, t), t * 1e-5);
  }
  push(word(Op::ListWritePort, port_bits));
}

void JobEncoder::send_jump_speed(std::uint16_t w) {
  push(word(Op::JumpSpeed, w));
  ++figures_.parameter_commands;
  jump_speed_ = w;
}

void JobEncoder::send_jump_delay(std::array<std::uint16_t, 2> d) {
  push(word(Op::JumpDelay, d[0], d[1]));
  ++figures_.parameter_commands;
  jump_delay_ = d;
  jump_delay_s_ = std::max(0.0, signed_s(d));
}

void JobEncoder::apply_pen(const BoardPen& p) {
  pen_ = &p;
  const auto param = [this](auto& have, auto value, const Word& c) {
    if (have == value) return;
    push(c);
    ++figures_.parameter_commands;
    have = value;
  };
  set_jump_speed(p.jump_speed);
  switch (p.source) {
    case LaserSource::fiber:
    case LaserSource::mopa:
      if (p.pulse_width) param(pulse_width_, *p.pulse_width, word(Op::FiberYLPMPulseWidth, *p.pulse_width));
      param(qswitch_, p.qswitch_period, word(Op::QSwitchPeriod, p.qswitch_period));
      param(power_, p.power, word(Op::MarkCurrent, p.power));
      break;
    case LaserSource::co2:
    case LaserSource::uv:
      param(mark_period_, p.mark_period, word(Op::MarkFreq, p.mark_period));
      param(fpk_, p.fpk, word(Op::SetCo2Fpk, p.fpk, p.fpk));
      param(power_ratio_, p.power_ratio, word(Op::MarkPowerRatio, p.power_ratio));
      break;
  }
  if (mark_speed_ != p.mark_speed) send_mark_speed(p.mark_speed);
  param(on_delay_, p.laser_on_delay, word(Op::LaserOnDelay, p.laser_on_delay[0], p.laser_on_delay[1]));
  param(off_delay_, p.laser_off_delay, word(Op::LaserOffDelay, p.laser_off_delay[0], p.laser_off_delay[1]));
  param(polygon_, p.polygon_delay, word(Op::PolygonDelay, p.polygon_delay[0], p.polygon_delay[1]));
  polygon_s_ = std::max(0.0, decode_polygon_delay(p.polygon_delay[0], p.polygon_delay[1], units_.polygon_unit()));
  polygon_worst_s_ = std::max(polygon_s_, decode_polygon_delay(p.polygon_delay[0], 0, PolygonDelayUnit::ten_us));
  set_jump_delay(p.jump_delay);
}

void JobEncoder::end_run() {
  if (!in_run_) return;
  in_run_ = false;
  if (pen_ && pen_->mark_delay_10us) push(word(Op::DelayTime, pen_->mark_delay_10us), pen_->mark_delay_10us * 1e-5);
}

inline void JobEncoder::push_move(Op op, std::array<std::uint16_t, 2> to, std::uint16_t v, bool corner) {
  const double length = segment_length(at_, to);
  // The estimate: length / speed (units per ms), the reciprocal cached per speed word; a
  // JumpTo is followed by the board's jump delay.
  if (v != inverse_for_) [[unlikely]] {
    inverse_for_ = v;
    inverse_speed_ = 1.0 / (double(v) * 1000.0);
  }
  double t = length * inverse_speed_;
  if (op == Op::JumpTo) t += jump_delay_s_;
  const std::array<std::int32_t, 2> d{std::int32_t(to[0]) - at_[0], std::int32_t(to[1]) - at_[1]};
  double unverified = 0;
  if (corner && polygon_worst_s_ > 0 && last_length_ > 0) [[unlikely]] {
    // PolygonDelay × (1 − cos φ), as the board's variable polygon delay (list_executor.hpp).
    const double cos_phi = double(d[0] * last_d_[0] + d[1] * last_d_[1]) / (length * last_length_);
    t += polygon_s_ * (1 - cos_phi);
    unverified = (polygon_worst_s_ - polygon_s_) * (1 - cos_phi);
  }
  last_d_ = d;
  last_length_ = length;
  push(word(op, to[0], to[1], 0, distance_word(length)), t, unverified);
  ++figures_.moves;
  at_ = to;
}

// Marks and jumps: nearly every command of a job, so this is the encoder's hot loop: one loop
// over the span with the move inline (add() → move() per command took 11 ns a command, this
// 8 ns: build/bench/bench_lmc, BM_LmcListEncoder40Rows). Parameter words go out of line: a
// speed change comes with one command in three.
std::size_t JobEncoder::add_moves(std::span<const DeviceCommand> cs, std::uint64_t first) {
  std::size_t i = 0;
  for (; i < cs.size(); ++i) {
    const DeviceCommand& c = cs[i];
    current_ = first + i;
    Op op;
    std::uint16_t v;
    bool corner = false;  // a MarkTo after a MarkTo: the board's polygon delay
    if (c.duration_s > 0) [[unlikely]] {
      add_timed(c);
      continue;
    }
    if (c.op == DeviceOp::mark && (c.speed_mm_s > 0 || pen_)) {
      op = Op::MarkTo;
      v = c.speed_mm_s > 0 ? encode_speed(c.speed_mm_s, units_, "mark speed") : pen_->mark_speed;
      if (mark_speed_ != v) [[unlikely]] send_mark_speed(v);
      corner = in_run_;
      in_run_ = true;
    } else if (c.op == DeviceOp::jump && c.speed_mm_s > 0) {
      // A blanking line: constant speed, no jump delay, and it does not end the mark run's
      // laser-off delay (the board runs that concurrently).
      op = Op::JumpTo;
      v = encode_speed(c.speed_mm_s, units_, "blanking line speed");
      in_run_ = false;
      set_jump_speed(v);
      set_jump_delay({0, 0});
    } else if (c.op == DeviceOp::jump && pen_) {
      // Travel at the pen's jump speed and delay, after the mark run's mark delay.
      op = Op::JumpTo;
      v = pen_->jump_speed;
      end_run();
      set_jump_speed(v);
      set_jump_delay(pen_->jump_delay);
    } else {
      break;  // a pen, a dwell, an arc, or a move at the pen's speed with no pen: add() does it
    }
    const auto to = units_.point(c.x_mm, c.y_mm);
    if (to[0] == at_[0] && to[1] == at_[1]) continue;  // nowhere to go (meerk40t drops these too)
    push_move(op, to, v, corner);
  }
  return i;
}

// A timed move (device_command.hpp): its speed word from the distance in units the board will
// travel, so the move takes the host's ticks; one that goes nowhere in units still takes its
// time, held like a dwell (dropping it would pull everything after it earlier).
void JobEncoder::add_timed(const DeviceCommand& c) {
  const auto to = units_.point(c.x_mm, c.y_mm);
  const double ticks = std::max(1.0, std::round(c.duration_s / kTick_s));
  const bool lit = c.op == DeviceOp::mark;
  if (lit && pen_) set_power(c.power_fraction);
  // On a board whose words take a tick (set_word_ticks), the move gives back what is owed, this
  // move's own speed and delay words included (counted before they are sent, as they would be
  // sent for the full-length move); a miscount by a word is settled by the moves after, since
  // the debt is kept from the words actually sent. A debt below zero lengthens the next move.
  const auto owed = [&](double words_to_come) {
    if (!word_ticks_ || !timed_) return 0.0;
    return std::min(tick_debt_ + words_to_come, ticks - 1);
  };
  if (to[0] == at_[0] && to[1] == at_[1]) {
    const double paid = owed(0);
    hold(ticks - paid, lit);
    tick_debt_ -= paid;
    timed_ = true;  // the first timed command's words delay the whole job alike: not owed
    return;
  }
  const double length = segment_length(at_, to);
  const char* what = lit ? "mark speed" : "blanking line speed";
  std::uint16_t v = timed_speed_word(length, ticks, units_, what);
  const double paid =
      owed(lit ? double(mark_speed_ != v)
               : double(jump_speed_ != v) + double(jump_delay_ != std::array<std::uint16_t, 2>{0, 0}));
  if (paid != 0) v = timed_speed_word(length, ticks - paid, units_, what);
  tick_debt_ -= paid;
  bool corner = false;
  if (lit) {
    if (mark_speed_ != v) send_mark_speed(v);
    corner = in_run_;
    in_run_ = true;
  } else {
    in_run_ = false;
    set_jump_speed(v);
    set_jump_delay({0, 0});
  }
  push_move(lit ? Op::MarkTo : Op::JumpTo, to, v, corner);
  timed_ = true;  // the first timed move's words delay the whole job alike: not owed
}

void JobEncoder::set_power(double fraction) {
  const auto send = [this](std::optional<std::uint16_t>& have, std::uint16_t w, Op op) {
    if (have == w) return;
    push(word(op, w));
    ++figures_.parameter_commands;
    have = w;
  };
  const double f = std::clamp(fraction, 0.0, 1.0);
  switch (pen_->source) {
    case LaserSource::fiber:
    case LaserSource::mopa:
      send(power_, static_cast<std::uint16_t>(std::lround(pen_->power * f)), Op::MarkCurrent);
      break;
    case LaserSource::co2:
    case LaserSource::uv:
      send(power_ratio_, static_cast<std::uint16_t>(std::lround(pen_->power_ratio * f)), Op::MarkPowerRatio);
      break;
  }
}

void JobEncoder::hold(double ticks, bool laser) {
  in_run_ = false;
  const Op op = laser ? Op::LaserOnPoint : Op::DelayTime;
  const double most = laser ? kMaxDwellTicks : kMaxDelayTicks;
  while (ticks > 0) {
    const double n = std::min(ticks, most);
    push(word(op, static_cast<std::uint16_t>(n)), n * 1e-5);
    ticks -= n;
  }
}

void JobEncoder::send_mark_speed(std::uint16_t w) {
  push(word(Op::MarkSpeed, w));
  ++figures_.parameter_commands;
  mark_speed_ = w;
}

void JobEncoder::add(const DeviceCommand& c, std::uint64_t index) {
  if (add_moves({&c, 1}, index) == 1) return;
  current_ = index;
  switch (c.op) {
    case DeviceOp::pen:
      // The caller resolves the index to a BoardPen and calls apply_pen; nothing on the wire.
      return;
    case DeviceOp::mark:
    case DeviceOp::jump:
      throw EncodeError("lmc: command " + std::to_string(index) +
                        " uses the pen's speed before any pen was applied");
    case DeviceOp::dwell:
      hold(std::round(c.dwell_s * 1e5), c.laser);
      return;
    case DeviceOp::arc:
      throw EncodeError("lmc: command " + std::to_string(index) +
                        " is an arc; the board takes no arcs (describe().arcs = false): chord it");
  }
}

void JobEncoder::add(std::span<const DeviceCommand> cs, std::uint64_t first,
                     std::span<const BoardPen> pens) {
  for (std::size_t i = add_moves(cs, first); i < cs.size(); i += add_moves(cs.subspan(i), first + i)) {
    const DeviceCommand& c = cs[i];
    add(c, first + i);
    if (c.op == DeviceOp::pen) {
      if (c.pen >= pens.size())
        throw EncodeError("lmc: command " + std::to_string(first + i) + " selects pen " +
                          std::to_string(c.pen) + "; the job has " + std::to_string(pens.size()));
      apply_pen(pens[c.pen]);
    }
    ++i;
  }
}

void JobEncoder::finish(std::uint64_t commands_in_job) {
  current_ = commands_in_job;
  end_run();
  push(word(Op::EndOfList));
  emit_packet(PacketInfo{commands_in_job, packet_estimate_s_, true, packet_estimate_s_ + packet_unverified_s_});
}

}  // namespace mark::lmc
