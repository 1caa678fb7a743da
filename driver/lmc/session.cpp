#include "driver/lmc/session.hpp"

#include <algorithm>
#include <cstdio>
#include <thread>

namespace mark::lmc {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

}  // namespace

std::string_view to_string(LinkFailure failure) {
  switch (failure) {
    case LinkFailure::timeout: return "timeout";
    case LinkFailure::stall: return "stall";
    case LinkFailure::no_device: return "no device";
    case LinkFailure::io: return "i/o error";
  }
  return "?";
}

Session::Session(LmcLink& link, SessionOptions options, const std::atomic<bool>& abort_requested)
    : link_(link), options_(options), abort_(abort_requested) {}

void Session::check_abort(bool stopping) const {
  if (!stopping && abort_.load(std::memory_order_acquire)) throw Aborted();
}

Reply Session::transact(const Word& c, bool stopping) {
  std::lock_guard lock(wire_);
  check_abort(stopping);
  const auto out = bytes(c);
  link_.write(out);
  ++figures_.single_commands;
  figures_.last_ok = Clock::now();
  const CommandSpec* spec = find_command(c.opcode());
  if (spec && !spec->reply) return Reply{};
  const Reply r = decode_reply(link_.read());
  figures_.last_ok = Clock::now();
  return r;
}

Reply Session::command(const Word& c) { return transact(c, false); }

std::uint16_t Session::poll_locked() {
  ++figures_.status_polls;
  return transact(word(Op::GetVersion), false).status();
}

std::uint16_t Session::poll_status() { return poll_locked(); }

std::array<std::uint16_t, 2> Session::position() {
  const Reply r = command(word(Op::GetPositionXY));
  return {r.w[1], r.w[2]};
}

void Session::sleep_poll() const {
  std::this_thread::sleep_for(std::chrono::duration<double>(options_.poll_interval_s));
}

BoardIdentity Session::initialise(const InitParams& p, const CorrectionTable* table) {
  BoardIdentity id;
  id.serial = serial_string(command(word(Op::GetSerialNo)));
  const Reply v = command(word(Op::GetVersion));
  id.version = {v.w[0], v.w[1], v.w[2]};
  command(word(Op::Reset));
  // Not in the reference sequences: a session that died mid-job may have left the laser
  // enable bit (or the red pointer) set; every output starts off.
  command(word(Op::WritePort, 0));
  upload_correction(table);
  command(word(Op::EnableLaser));
  command(word(Op::SetControlMode, p.control_mode));
  command(word(Op::SetLaserMode, p.laser_mode));
  command(word(Op::SetDelayMode, p.delay_mode));
  command(word(Op::SetTiming, p.timing));
  command(word(Op::SetStandby, p.standby[0], p.standby[1]));
  command(word(Op::SetFirstPulseKiller, p.first_pulse_killer));
  command(word(Op::SetPwmHalfPeriod, p.pwm_half_period));
  command(word(Op::SetPwmPulseWidth, p.pwm_pulse_width));
  if (p.fiber) command(word(Op::FiberSetMo, 0));
  command(word(Op::SetFpkParam2, p.fpk2[0], p.fpk2[1], p.fpk2[2], p.fpk2[3]));
  command(word(Op::SetFlyRes, p.fly_res[0], p.fly_res[1], p.fly_res[2], p.fly_res[3]));
  command(word(Op::EnableZ));
  command(word(Op::WriteAnalogPort1, p.analog_port_1));
  command(word(Op::EnableZ));
  if (p.settle_s > 0) std::this_thread::sleep_for(std::chrono::duration<double>(p.settle_s));
  return id;
}

void Session::upload_correction(const CorrectionTable* table) {
  if (!table) {
    command(word(Op::WriteCorTable, 0));
    return;
  }
  if (table->entries.size() != kCorEntries)
    throw CorFileError("lmc: a correction table needs " + std::to_string(kCorEntries) +
                       " entries, this one has " + std::to_string(table->entries.size()));
  command(word(Op::WriteCorTable, 1));
  bool first = true;
  for (const auto& e : table->entries) {
    command(word(Op::WriteCorLine, e[0], e[1], first ? 0 : 1));  // no reply (galvo.md §1.2)
    first = false;
  }
}

void Session::begin_list() {
  packets_in_list_ = 0;
  executed_ = false;
  queued_s_ = 0;
  paused_s_ = 0;
}

void Session::write_packet(const ListPacket& packet, bool stopping) {
  std::lock_guard lock(wire_);
  check_abort(stopping);
  link_.write(packet.bytes());
  figures_.last_ok = Clock::now();
  if (!figures_.first_packet_at) figures_.first_packet_at = Clock::now();
  ++figures_.packets;
  transact(word(Op::SetEndOfList, 0), stopping);
}

// Polls the status until `done` holds for it. The board can never take longer than the work
// queued on it, so the deadline is what is left of that estimate since ExecuteList (time
// paused not counted) plus the grace period. Returns the seconds waited, 0 if the first poll
// was enough; throws BoardTimeout saying what it waited for.
template <class Done>
double Session::poll_until(Done done, const std::string& waiting_for) {
  const auto t0 = Clock::now();
  auto last = t0;
  double paused_here = 0;
  for (bool first = true;; first = false) {
    if (done(poll_locked())) {
      paused_s_ += paused_here;
      return first ? 0 : seconds_since(t0);
    }
    const auto now = Clock::now();
    if (paused_.load()) paused_here += std::chrono::duration<double>(now - last).count();
    last = now;
    double remaining = queued_s_;
    if (executed_)
      remaining -= std::chrono::duration<double>(now - execute_start_).count() - paused_s_ - paused_here;
    remaining = std::max(0.0, remaining);
    const double waited = std::chrono::duration<double>(now - t0).count();
    if (waited - paused_here > remaining + options_.grace_s) {
      char buf[240];
      std::snprintf(buf, sizeof buf,
                    "lmc: the board did not %s within %.2f s (its queued work was estimated at "
                    "%.2f s)",
                    waiting_for.c_str(), waited, remaining);
      throw BoardTimeout(buf);
    }
    sleep_poll();
  }
}

void Session::send_packet(const ListPacket& packet, double estimated_s) {
  const double waited = poll_until([](std::uint16_t s) { return (s & status::ready) != 0; },
                                   "become READY for list packet " +
                                       std::to_string(packets_in_list_ + 1));
  if (waited > 0) {
    std::lock_guard lock(wire_);
    ++figures_.ready_waits;
    figures_.ready_wait_s += waited;
  }
  write_packet(packet, false);
  ++packets_in_list_;
  queued_s_ += estimated_s;
  if (!executed_ && packets_in_list_ >= options_.execute_after_packets) finish_list();
}

void Session::finish_list() {
  if (executed_) return;
  command(word(Op::ExecuteList));
  executed_ = true;
  execute_start_ = Clock::now();
  if (!figures_.execute_at) figures_.execute_at = execute_start_;
}

void Session::wait_idle() {
  poll_until([](std::uint16_t s) { return (s & status::busy) == 0; }, "finish its list (still BUSY)");
}

SessionFigures Session::figures() {
  std::lock_guard lock(wire_);
  return figures_;
}

void Session::pause() {
  paused_ = true;
  command(word(Op::StopList));
}

void Session::resume() {
  command(word(Op::RestartList));
  paused_ = false;
}

StopOutcome Session::stop(std::uint16_t port_off, bool fiber) noexcept {
  StopOutcome out;
  std::lock_guard lock(wire_);
  // One step: on a stall clear the halt and retry once; any other failure ends the sequence.
  const auto step = [&](const Word& c) -> bool {
    for (int attempt = 0; attempt < 2; ++attempt) {
      try {
        transact(c, true);
        out.reached = true;
        return true;
      } catch (const LinkError& e) {
        if (e.failure() == LinkFailure::stall && attempt == 0) {
          try {
            link_.clear_halt();
            continue;
          } catch (const std::exception& e2) {
            out.note = e2.what();
            return false;
          }
        }
        out.note = e.what();
        return false;
      } catch (const std::exception& e) {
        out.note = e.what();
        return false;
      }
    }
    return false;
  };
  if (!step(word(Op::WritePort, port_off))) return out;
  out.laser_off_confirmed = true;
  if (!step(word(Op::StopExecute))) return out;
  paused_ = false;
  if (fiber && !step(word(Op::FiberSetMo, 0))) return out;
  if (!step(word(Op::ResetList))) return out;
  // Flush, as meerk40t does after a stop: an empty list, started at once. Only when the board
  // has room — a stop must never wait for READY.
  try {
    if (transact(word(Op::GetVersion), true).ready()) {
      ListPacket flush;
      flush.push(word(Op::EndOfList));
      write_packet(flush, true);
      transact(word(Op::ExecuteList), true);
    }
  } catch (const std::exception& e) {
    out.note = e.what();
    return out;
  }
  step(word(Op::WritePort, port_off));
  return out;
}

}  // namespace mark::lmc
