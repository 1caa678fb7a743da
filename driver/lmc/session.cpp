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
  if (p.enable_laser) command(word(Op::EnableLaser));
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
  queued_s_ = allowed_s_ = 0;
  std::lock_guard lock(pause_mutex_);
  paused_ = false;
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

double Session::paused_total_s() const {
  std::lock_guard lock(pause_mutex_);
  return paused_s_ + (paused_ ? seconds_since(paused_at_) : 0.0);
}

double Session::running_s() const {
  if (!executed_) return 0;
  return std::max(0.0, seconds_since(execute_start_) - paused_total_s());
}

// Polls the status until `done` holds for it; see the top of session.hpp for when it gives up.
// Returns the seconds waited, 0 if the first poll was enough; throws BoardTimeout saying what
// it waited for, how long the board has run and what it was given.
template <class Done>
double Session::poll_until(Done done, const char* waiting_for) {
  const auto t0 = Clock::now();
  for (bool first = true;; first = false) {
    const std::uint16_t status = poll_locked();
    if (done(status)) return first ? 0 : seconds_since(t0);
    if (!executed_) {
      // Not READY and nothing running: the board's buffer filled before the packet that
      // starts the list. Start it, or READY never comes back.
      if ((status & status::ready) == 0) finish_list();
      sleep_poll();
      continue;
    }
    const double ran = running_s();
    const double allowed = (1 + options_.estimate_margin) * allowed_s_ + options_.grace_s;
    if (ran > allowed) {
      char buf[360];
      std::snprintf(buf, sizeof buf,
                    "lmc: the board did not %s: it has run its list for %.2f s since ExecuteList "
                    "(time paused not counted), and what it was sent was estimated at %.2f s, at "
                    "most %.2f s (allowed %.2f s: %.0f %% more, and %.1f s); it answers but is not "
                    "getting through the list",
                    waiting_for, ran, queued_s_, allowed_s_, allowed, 100 * options_.estimate_margin,
                    options_.grace_s);
      throw BoardTimeout(buf);
    }
    sleep_poll();
  }
}

void Session::send_packet(const ListPacket& packet, double estimated_s, double allowance_s) {
  const double waited = poll_until([](std::uint16_t s) { return (s & status::ready) != 0; },
                                   "become READY for the next list packet");
  if (waited > 0) {
    std::lock_guard lock(wire_);
    ++figures_.ready_waits;
    figures_.ready_wait_s += waited;
  }
  write_packet(packet, false);
  ++packets_in_list_;
  queued_s_ += estimated_s;
  allowed_s_ += std::max(estimated_s, allowance_s);
  if (!executed_ && packets_in_list_ >= options_.execute_after_packets) finish_list();
}

void Session::finish_list() {
  if (executed_) return;
  command(word(Op::ExecuteList));
  executed_ = true;
  execute_start_ = Clock::now();
  {
    std::lock_guard lock(pause_mutex_);
    paused_s_ = 0;
    if (paused_) paused_at_ = execute_start_;
  }
  std::lock_guard lock(wire_);
  if (!figures_.execute_at) figures_.execute_at = execute_start_;
}

void Session::wait_idle() {
  const double waited =
      poll_until([](std::uint16_t s) { return (s & status::busy) == 0; }, "finish its list (still BUSY)");
  std::lock_guard lock(wire_);
  figures_.idle_wait_s += waited;
}

SessionFigures Session::figures() {
  std::lock_guard lock(wire_);
  return figures_;
}

void Session::pause() {
  {
    std::lock_guard lock(pause_mutex_);
    if (!paused_) paused_at_ = Clock::now();
    paused_ = true;
  }
  command(word(Op::StopList));
}

void Session::resume() {
  command(word(Op::RestartList));
  std::lock_guard lock(pause_mutex_);
  if (paused_) paused_s_ += seconds_since(paused_at_);
  paused_ = false;
}

std::string_view to_string(StopStep::Result result) {
  switch (result) {
    case StopStep::Result::acknowledged: return "acknowledged";
    case StopStep::Result::unanswered: return "written, no answer";
    case StopStep::Result::not_written: return "not written";
    case StopStep::Result::unreachable: return "not tried, the board is gone";
    case StopStep::Result::skipped: return "skipped";
  }
  return "?";
}

std::string StopOutcome::summary() const {
  std::string acked, missing;
  for (const StopStep& s : steps) {
    if (s.result == StopStep::Result::acknowledged) {
      acked += (acked.empty() ? "" : ", ") + s.command;
    } else if (s.result != StopStep::Result::skipped) {
      missing += (missing.empty() ? "" : "; ") + s.command + " " + std::string(to_string(s.result)) +
                 (s.why.empty() ? "" : " (" + s.why + ")");
    }
  }
  std::string out = stopped ? "stopped" : "NOT confirmed stopped";
  if (!stopped)
    out += " (StopExecute and Fiber_SetMo(0) must both be acknowledged)";
  out += laser_off_confirmed ? ", laser port off confirmed" : ", laser port off NOT confirmed";
  if (!acked.empty()) out += "; acknowledged: " + acked;
  if (!missing.empty()) out += "; " + missing;
  if (!reached) out += "; the board could not be reached";
  return out;
}

StopOutcome Session::stop(std::uint16_t port_off) noexcept {
  StopOutcome out;
  try {
    std::lock_guard lock(wire_);
    bool gone = false;
    int unwritten = 0;  // commands in a row whose write failed
    Reply last;  // the answer to the last acknowledged command
    // One command: written whatever came before; a stall is cleared and the command written
    // once more; a vanished board ends what can be tried.
    const auto step = [&](const Word& c, std::string name, bool last_chance = false) -> StopStep& {
      StopStep& st = out.steps.emplace_back();
      st.command = std::move(name);
      if (gone) return st;  // unreachable
      if (unwritten >= 2 && !last_chance) {
        // Two writes in a row took the link's whole timeout and went nowhere: the board takes
        // nothing now. Only the closing WritePort is still tried.
        st.result = StopStep::Result::not_written;
        st.why = "not tried: the two commands before it could not be written";
        return st;
      }
      for (int attempt = 0; attempt < 2; ++attempt) {
        bool written = false;
        try {
          link_.write(bytes(c));
          written = true;
          ++figures_.single_commands;
          figures_.last_ok = Clock::now();
          const CommandSpec* spec = find_command(c.opcode());
          if (spec && spec->reply) last = decode_reply(link_.read());
          figures_.last_ok = Clock::now();
          st.result = StopStep::Result::acknowledged;
          st.why.clear();
          out.reached = true;
          unwritten = 0;
          return st;
        } catch (const LinkError& e) {
          st.why = e.what();
          st.result = written ? StopStep::Result::unanswered : StopStep::Result::not_written;
          unwritten = written ? 0 : unwritten + 1;
          if (e.failure() == LinkFailure::no_device) {
            gone = true;
            return st;
          }
          if (e.failure() == LinkFailure::stall && attempt == 0) {
            try {
              link_.clear_halt();
              continue;
            } catch (const std::exception& e2) {
              st.why += std::string("; clearing the stall failed: ") + e2.what();
            }
          }
          return st;
        } catch (const std::exception& e) {
          st.why = e.what();
          st.result = written ? StopStep::Result::unanswered : StopStep::Result::not_written;
          return st;
        }
      }
      return st;
    };
    char port[32];
    std::snprintf(port, sizeof port, "WritePort(0x%04X)", port_off);
    out.laser_off_confirmed = step(word(Op::WritePort, port_off), port).result == StopStep::Result::acknowledged;
    const bool executed_stopped = step(word(Op::StopExecute), "StopExecute").result == StopStep::Result::acknowledged;
    {
      std::lock_guard pause_lock(pause_mutex_);
      paused_ = false;
    }
    const bool mo_closed = step(word(Op::FiberSetMo, 0), "Fiber_SetMo(0)").result == StopStep::Result::acknowledged;
    step(word(Op::ResetList), "ResetList");
    // Flush, as meerk40t does after a stop: an empty list, started at once. Only when the board
    // has room — a stop never waits for READY.
    const bool ready = step(word(Op::GetVersion), "GetVersion (READY for the flush list?)").result ==
                           StopStep::Result::acknowledged &&
                       last.ready();
    StopStep& flush = out.steps.emplace_back();
    flush.command = "flush list (EndOfList, ExecuteList)";
    if (gone) {
      flush.result = StopStep::Result::unreachable;
    } else if (!ready) {
      flush.result = StopStep::Result::skipped;
    } else {
      try {
        ListPacket empty;
        empty.push(word(Op::EndOfList));
        write_packet(empty, true);
        transact(word(Op::ExecuteList), true);
        flush.result = StopStep::Result::acknowledged;
      } catch (const LinkError& e) {
        flush.result = StopStep::Result::not_written;
        flush.why = e.what();
        if (e.failure() == LinkFailure::no_device) gone = true;
      } catch (const std::exception& e) {
        flush.result = StopStep::Result::not_written;
        flush.why = e.what();
      }
    }
    if (step(word(Op::WritePort, port_off), port, true).result == StopStep::Result::acknowledged)
      out.laser_off_confirmed = true;
    out.stopped = executed_stopped && mo_closed;
  } catch (...) {
    // Only allocation can throw here; what was recorded stands.
  }
  return out;
}

}  // namespace mark::lmc
