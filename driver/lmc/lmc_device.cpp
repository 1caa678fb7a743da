#include "driver/lmc/lmc_device.hpp"

#include <cmath>
#include <cstdio>

namespace mark::lmc {
namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

std::string point_text(double x, double y) {
  char buf[80];
  std::snprintf(buf, sizeof buf, "(%.4f, %.4f) mm", x, y);
  return buf;
}

const char* op_name(DeviceOp op) {
  switch (op) {
    case DeviceOp::pen: return "pen";
    case DeviceOp::jump: return "jump";
    case DeviceOp::mark: return "mark";
    case DeviceOp::arc: return "arc";
    case DeviceOp::dwell: return "dwell";
  }
  return "?";
}

// One dwell command longer than this is surely a unit mistake (an hour).
constexpr double kLongestDwell_s = 3600;

}  // namespace

LmcDevice::LmcDevice(std::unique_ptr<LmcLink> link, LmcOptions options)
    : options_(std::move(options)),
      units_(options_.field_mm, options_.axes, options_.polygon_delay_unit),
      link_(std::move(link)),
      session_(*link_, options_.session, lifecycle_.abort_flag()),
      encoder_(units_, [this](const ListPacket& p, const PacketInfo& i) { send_packet(p, i); }) {
  encoder_.set_word_ticks(options_.word_ticks);
  const auto bit_ok = [](int b) { return b >= 0 && b < 16; };
  if (!bit_ok(options_.laser_port_bit) || !bit_ok(options_.red_pointer_bit) ||
      options_.laser_port_bit == options_.red_pointer_bit)
    throw DeviceError("lmc: the laser and red-pointer port bits must be two different bits 0..15");
  if (!(options_.chord_tolerance_mm > 0) || options_.chord_tolerance_mm > 1)
    throw DeviceError("lmc: chord tolerance must be in (0, 1] mm");
  if (options_.correction) check_cor_lens(*options_.correction, options_.field_mm);
  try {
    identity_ = session_.initialise(options_.init,
                                    options_.correction ? &*options_.correction : nullptr);
  } catch (const LinkError& e) {
    throw DeviceFaultError(DeviceFault{
        e.failure() == LinkFailure::timeout ? FaultCategory::timeout : FaultCategory::transport,
        "lmc: " + link_->name() + " did not complete the init sequence: " + e.what(), 0});
  }
  link_->remember_serial(identity_.serial);
  lifecycle_.rename("lmc " + identity_.serial);
}

LmcDevice::~LmcDevice() {
  // A device going away mid-job (an exception unwinding the caller) must not leave the laser on.
  if (lifecycle_.state() == DeviceState::running) abort();
}

DeviceDescription LmcDevice::describe() const {
  DeviceDescription d;
  d.name = "lmc " + identity_.serial;
  d.level = DeviceLevel::commands;
  d.field_mm = options_.field_mm;
  d.tick_s = 10e-6;
  d.arcs = false;
  d.chord_tolerance_mm = options_.chord_tolerance_mm;
  d.max_speed_mm_s = std::min(options_.max_speed_mm_s, 65535.0 * 1000.0 / units_.units_per_mm());
  d.max_dwell_s = 0;  // long dwells are split into several commands
  d.laser_settings = true;
  return d;
}

// The one place a port word is composed: the laser and red-pointer bits this device owns, and
// the station's signal bits (which set_signal_bits() keeps clear of those two).
std::uint16_t LmcDevice::port_bits(bool laser, bool red) const {
  return static_cast<std::uint16_t>((laser ? 1u << options_.laser_port_bit : 0u) |
                                    (red ? 1u << options_.red_pointer_bit : 0u) |
                                    signals_.load(std::memory_order_acquire));
}

std::uint16_t LmcDevice::reserved_port_bits() const {
  return static_cast<std::uint16_t>((1u << options_.laser_port_bit) | (1u << options_.red_pointer_bit));
}

void LmcDevice::set_signal_bits(std::uint16_t bits) noexcept {
  signals_.store(static_cast<std::uint16_t>(bits & ~reserved_port_bits()), std::memory_order_release);
}

std::uint16_t LmcDevice::read_inputs() { return session_.command(word(Op::ReadPort)).w[1]; }

bool LmcDevice::write_outputs() {
  std::lock_guard job(job_);
  if (lifecycle_.state() == DeviceState::running) return false;
  session_.command(word(Op::WritePort, port_bits(false, red_on_.load())));
  return true;
}

void LmcDevice::begin_job(const JobHeader& header) {
  std::lock_guard job(job_);
  lifecycle_.require(DeviceState::idle, "begin_job", "a job begins on an idle device (reset() it first)");
  if (!(header.field_mm > 0) || header.field_mm > options_.field_mm * (1 + 1e-9)) {
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "lmc: job '%s' needs a %g mm field, the lens gives %g mm (allowed up to %g mm)",
                  header.name.c_str(), header.field_mm, options_.field_mm, options_.field_mm);
    throw DeviceError(buf);
  }
  if (header.pens.empty()) throw DeviceError("lmc: job '" + header.name + "' has no pen");
  std::vector<BoardPen> pens;
  for (std::size_t i = 0; i < header.pens.size(); ++i) {
    // One machine, one source: a pen for another source would send words the laser does not
    // understand (a CO2 power ratio to a fiber's driver).
    if (header.pens[i].laser.source != header.pens[0].laser.source)
      throw DeviceError("lmc: job '" + header.name + "': pen " + std::to_string(i) + " is for a " +
                        std::string(to_string(header.pens[i].laser.source)) + " source, pen 0 for " +
                        std::string(to_string(header.pens[0].laser.source)) +
                        "; a board drives one source");
    pens.push_back(encode_pen(header.pens[i], i, units_));  // refusals first
  }

  header_ = header;
  header_.lit_paths.clear();  // not needed here; do not keep a copy of the geometry
  pens_ = std::move(pens);
  source_ = header.pens[0].laser.source;
  commands_ = commands_sent_ = 0;
  packets_ = 0;
  list_commands_at_start_ = encoder_.figures().list_commands;
  parameters_at_start_ = encoder_.figures().parameter_commands;
  moves_at_start_ = encoder_.figures().moves;
  estimate_at_start_s_ = encoder_.figures().estimated_s;
  session_at_start_ = session_.figures();
  first_packet_s_ = -1;
  fault_latency_s_ = -1;
  device_time_s_ = 0;
  job_start_ = Clock::now();
  lifecycle_.begin("begin_job");
  {
    std::lock_guard lock(report_mutex_);
    last_stop_.reset();
  }
  try {
    // As meerk40t's program mode: a fresh list, the laser enable bit, a fiber's master
    // oscillator open, then ReadyMark, its open-MO delay, the port in the list, and the first
    // pen (the preamble: every setting, job_encoder.hpp).
    const bool mo = limits_of(source_).master_oscillator;
    session_.command(word(Op::ResetList));
    session_.command(word(Op::WritePort, port_bits(true, false)));
    if (mo) session_.command(word(Op::FiberSetMo, 1));
    laser_on_ = true;
    session_.begin_list();
    encoder_.start_list(mo ? options_.open_mo_delay_s : 0, port_bits(true, false));
    encoder_.apply_pen(pens_[0]);
  } catch (const Aborted&) {
    return;
  } catch (const std::exception& e) {
    fail_from(e);
  }
}

void LmcDevice::check_commands(std::span<const DeviceCommand> cs) const {
  for (std::size_t i = 0; i < cs.size(); ++i) {
    const DeviceCommand& c = cs[i];
    const std::uint64_t at = commands_ + i;
    const auto refuse = [&](FaultCategory cat, const std::string& why) {
      throw DeviceFaultError(DeviceFault{
          cat, "lmc: command " + std::to_string(at) + " (" + op_name(c.op) + ") refused before "
                   "anything of it was sent: " + why, at});
    };
    switch (c.op) {
      case DeviceOp::pen:
        if (c.pen >= pens_.size())
          refuse(FaultCategory::device, "pen " + std::to_string(c.pen) + " is not in the job's " +
                                            std::to_string(pens_.size()) + " pens");
        break;
      case DeviceOp::arc:
        refuse(FaultCategory::device, "the board takes no arcs (describe().arcs = false): chord "
                                      "them to describe().chord_tolerance_mm");
        break;
      case DeviceOp::jump:
      case DeviceOp::mark:
        if (!units_.in_field(c.x_mm, c.y_mm)) {
          char buf[120];
          std::snprintf(buf, sizeof buf, " lies outside the %g mm field (|x|, |y| ≤ %g mm)",
                        options_.field_mm, units_.half_field_mm());
          refuse(FaultCategory::out_of_field, point_text(c.x_mm, c.y_mm) + buf);
        }
        if (!(c.speed_mm_s >= 0) || !std::isfinite(c.speed_mm_s))
          refuse(FaultCategory::device, "speed " + std::to_string(c.speed_mm_s) +
                                            " mm/s is not a speed (0 = the pen's, or > 0)");
        break;
      case DeviceOp::dwell:
        if (!(c.dwell_s >= 0) || c.dwell_s > kLongestDwell_s)
          refuse(FaultCategory::device, "dwell " + std::to_string(c.dwell_s) +
                                            " s is outside 0 .. 3600 s");
        break;
    }
  }
}

void LmcDevice::submit(std::span<const DeviceCommand> commands) {
  std::lock_guard job(job_);
  switch (lifecycle_.state()) {
    case DeviceState::running: break;
    case DeviceState::aborted: return;  // the caller aborted: nothing more goes out
    case DeviceState::failed:
      if (const auto f = lifecycle_.fault()) throw DeviceFaultError(*f);
      [[fallthrough]];
    default: lifecycle_.refuse("submit", "commands go to a running job (begin_job)");
  }
  try {
    check_commands(commands);
  } catch (const DeviceFaultError& e) {
    fail(e.fault().category, e.fault().message);
  }
  try {
    // The DeviceCommand contract: a job starts at the field centre. When the mirrors are
    // elsewhere (an earlier job) and the job begins with anything but a jump, go there first.
    if (commands_ == 0 && !commands.empty() && commands.front().op != DeviceOp::jump &&
        encoder_.position() != std::array<std::uint16_t, 2>{0x8000, 0x8000})
      encoder_.add(DeviceCommand::jump_to(0, 0), 0);
    encoder_.add(commands, commands_, pens_);
    commands_ += commands.size();
    const auto p = units_.field_point(encoder_.position()[0], encoder_.position()[1]);
    std::lock_guard lock(report_mutex_);
    position_ = {p[0], p[1]};
  } catch (const Aborted&) {
    return;
  } catch (const std::exception& e) {
    fail_from(e);
  }
}

void LmcDevice::send_packet(const ListPacket& packet, const PacketInfo& info) {
  session_.send_packet(packet, info.estimated_s, info.allowance_s);
  commands_sent_ = info.commands_complete;
  if (packets_ == 0) first_packet_s_ = seconds(Clock::now() - job_start_);
  ++packets_;
  if (info.last) session_.finish_list();
}

DeviceReport LmcDevice::end_job() {
  std::lock_guard job(job_);
  const DeviceState s = lifecycle_.state();
  if (s == DeviceState::idle) lifecycle_.refuse("end_job", "no job was begun");
  if (s == DeviceState::running) {
    try {
      encoder_.finish(commands_);
      session_.finish_list();
      const auto started = session_.figures().execute_at.value_or(Clock::now());
      session_.wait_idle();
      device_time_s_ = seconds(Clock::now() - started);
      // Executed in full. Close the oscillator and the laser port (meerk40t's rapid mode).
      commands_sent_ = commands_;
      session_.command(word(Op::FiberSetMo, 0));
      session_.command(word(Op::WritePort, port_bits(false, false)));
      laser_on_ = false;
      session_.command(word(Op::GetMarkTime, 3));
      link_->flush();
      lifecycle_.end();  // done, unless abort() came first
    } catch (const Aborted&) {
    } catch (const DeviceFaultError&) {
    } catch (const std::exception& e) {
      try {
        fail_from(e);
      } catch (const DeviceFaultError&) {
      }
    }
  }
  collect_figures();
  return report();
}

void LmcDevice::collect_figures() {
  const EncoderFigures& e = encoder_.figures();
  const SessionFigures s = session_.figures();
  const double list_commands = double(e.list_commands - list_commands_at_start_);
  const double packets = double(packets_);
  DeviceFigures f = {
      {"commands", double(commands_)},
      {"list_commands", list_commands},
      {"packets", packets},
      {"list_commands_per_packet", packets > 0 ? list_commands / packets : 0},
      {"moves", double(e.moves - moves_at_start_)},
      {"parameter_commands", double(e.parameter_commands - parameters_at_start_)},
      {"single_commands", double(s.single_commands - session_at_start_.single_commands)},
      {"status_polls", double(s.status_polls - session_at_start_.status_polls)},
      {"ready_waits", double(s.ready_waits - session_at_start_.ready_waits)},
      {"ready_wait_s", s.ready_wait_s - session_at_start_.ready_wait_s},
      {"idle_wait_s", s.idle_wait_s - session_at_start_.idle_wait_s},
      {"estimated_time_s", e.estimated_s - estimate_at_start_s_},
  };
  f.emplace_back("lens_mm", options_.field_mm);
  if (options_.correction) f.emplace_back("cor_lens_mm", options_.correction->lens_mm());
  if (first_packet_s_ >= 0) f.emplace_back("first_packet_s", first_packet_s_);
  if (fault_latency_s_ >= 0) f.emplace_back("fault_latency_s", fault_latency_s_);
  const DeviceState state = lifecycle_.state();
  std::lock_guard lock(report_mutex_);
  if (last_stop_ && state != DeviceState::done) {
    // How the job's stop went: 1 when StopExecute and Fiber_SetMo(0) were acknowledged, and how
    // many of its commands were not (the fault message names them).
    double unacknowledged = 0;
    for (const StopStep& st : last_stop_->steps)
      unacknowledged += st.result != StopStep::Result::acknowledged && st.result != StopStep::Result::skipped;
    f.emplace_back("stop_confirmed", last_stop_->stopped ? 1 : 0);
    f.emplace_back("stop_unacknowledged", unacknowledged);
  }
  figures_ = std::move(f);
}

void LmcDevice::fail_from(const std::exception& e) {
  if (const auto* le = dynamic_cast<const LinkError*>(&e))
    fail(le->failure() == LinkFailure::timeout ? FaultCategory::timeout : FaultCategory::transport,
         e.what());
  if (dynamic_cast<const BoardTimeout*>(&e)) fail(FaultCategory::timeout, e.what());
  if (const auto* fe = dynamic_cast<const DeviceFaultError*>(&e))
    fail(fe->fault().category, fe->fault().message);
  fail(FaultCategory::device, e.what());
}

void LmcDevice::fail(FaultCategory category, const std::string& what) {
  const auto detected = Clock::now();
  const SessionFigures f = session_.figures();
  if (f.last_ok != Clock::time_point{}) fault_latency_s_ = seconds(detected - f.last_ok);
  const std::string stopped = stop_board();
  DeviceFault fault;
  fault.category = category;
  // What was and was not marked. Before ExecuteList nothing ran; after it, everything whose
  // list commands reached the board may have been executed, and nothing after that was.
  fault.at = session_.executing() ? commands_sent_.load() : 0;
  std::string marked;
  if (fault.at == 0)
    marked = "nothing was marked (the board had not started the list)";
  else
    marked = "commands 0.." + std::to_string(fault.at - 1) +
             " were sent and may have been marked; nothing from command " +
             std::to_string(fault.at) + " on was marked";
  fault.message = what + "; " + marked + "; " + stopped;
  collect_figures();
  try {
    link_->flush();  // a capture keeps what was sent
  } catch (...) {
  }
  throw DeviceFaultError(lifecycle_.fail(fault));
}

std::string LmcDevice::stop_board() noexcept {
  try {
    StopOutcome o = session_.stop(port_bits(false, false));
    if (o.laser_off_confirmed) laser_on_ = false;
    std::string summary = o.summary();
    std::lock_guard lock(report_mutex_);
    last_stop_ = std::move(o);
    return summary;
  } catch (...) {
    return "the stop sequence failed";
  }
}

StopOutcome LmcDevice::last_stop() const {
  std::lock_guard lock(report_mutex_);
  return last_stop_.value_or(StopOutcome{});
}

void LmcDevice::abort() noexcept {
  // The request first: the session's waits see it and the producer's submit() stops sending.
  lifecycle_.abort();
  stop_board();
}

DeviceStatus LmcDevice::status() const {
  DeviceStatus s = lifecycle_.snapshot();
  s.laser_on = laser_on_ && s.state == DeviceState::running;
  s.progress = commands_sent_;
  std::lock_guard lock(report_mutex_);
  s.position = position_;
  return s;
}

void LmcDevice::reset() {
  std::lock_guard job(job_);
  const DeviceState s = lifecycle_.state();
  const std::optional<DeviceFault> f = lifecycle_.fault();
  // Idle now (refused while running): the session may talk to the board again.
  lifecycle_.reset();
  try {
    if (f && (f->category == FaultCategory::transport || f->category == FaultCategory::timeout)) {
      // The link failed: find the board again (it may have been replugged) and initialise it.
      link_->reopen();
      identity_ = session_.initialise(options_.init,
                                      options_.correction ? &*options_.correction : nullptr);
    }
    // After a stop the mirrors are wherever they stopped: ask, so the next jump's length is
    // right. (After a finished job the encoder knows where it left them.)
    if (s == DeviceState::aborted || s == DeviceState::failed) encoder_.set_position(session_.position());
  } catch (const std::exception& e) {
    // Not back: the device stays out of service (failed) until a reset() reaches the board.
    throw DeviceFaultError(lifecycle_.fail(DeviceFault{
        FaultCategory::transport, "lmc: reset could not reach the board: " + std::string(e.what()), 0}));
  }
}

DeviceReport LmcDevice::report() const {
  DeviceReport r;
  const DeviceStatus st = lifecycle_.snapshot();
  r.outcome = st.state;
  r.fault = st.fault;
  // Done: everything. Failed: what the fault says. Aborted: what had been sent, if the list had
  // started (ExecuteList), else nothing.
  std::lock_guard lock(report_mutex_);
  r.commands_done = st.state == DeviceState::done ? commands_
                    : st.fault                     ? st.fault->at
                    : session_.executing()       ? commands_sent_.load()
                                                 : 0;
  r.device_time_s = device_time_s_;
  r.figures = figures_;
  return r;
}

void LmcDevice::pause() {
  lifecycle_.require(DeviceState::running, "pause", "a running job pauses");
  session_.pause();
}

void LmcDevice::resume() {
  lifecycle_.require(DeviceState::running, "resume", "a running job resumes");
  session_.resume();
}

Vec2 LmcDevice::query_position() {
  const auto w = session_.position();
  const auto p = units_.field_point(w[0], w[1]);
  return {p[0], p[1]};
}

std::uint16_t LmcDevice::query_status() { return session_.poll_status(); }

void LmcDevice::set_red_pointer(bool on) {
  std::lock_guard job(job_);
  if (lifecycle_.state() == DeviceState::running)
    lifecycle_.refuse("set_red_pointer", "the red pointer is switched between jobs");
  session_.command(word(Op::WritePort, port_bits(false, on)));
  red_on_.store(on);
}

FrameReport LmcDevice::frame(const std::vector<std::vector<Vec2>>& paths, const FrameOptions& o) {
  std::lock_guard job(job_);
  lifecycle_.require(DeviceState::idle, "frame", "a frame runs on an idle device (reset() it first)");
  std::size_t points = 0;
  for (const auto& path : paths)
    for (const Vec2& p : path) {
      if (!units_.in_field(p.x, p.y))
        throw DeviceFaultError(DeviceFault{
            FaultCategory::out_of_field,
            "lmc: frame point " + point_text(p.x, p.y) + " lies outside the " +
                std::to_string(options_.field_mm) + " mm field; nothing was sent", 0});
      ++points;
    }
  if (points == 0) throw DeviceError("lmc: frame: nothing to trace");
  encode_speed(o.speed_mm_s, units_, "red-pointer speed");  // refuse before sending

  FrameReport report;
  const std::uint64_t packets_before = packets_;
  lifecycle_.begin("frame");
  red_on_.store(false);  // however the frame ends, it leaves the red pointer off
  try {
    // The laser enable bit stays clear and the master oscillator closed for the whole frame.
    session_.command(word(Op::ResetList));
    session_.command(word(Op::FiberSetMo, 0));
    session_.command(word(Op::WritePort, port_bits(false, true)));
    session_.begin_list();
    encoder_.start_list(0, port_bits(false, true));
    std::uint64_t index = 0;
    while (o.laps == 0 || report.laps < o.laps) {
      for (const auto& path : paths)
        for (const Vec2& p : path) encoder_.add(DeviceCommand::jump_to(p.x, p.y, o.speed_mm_s), index++);
      ++report.laps;
    }
    encoder_.finish(index);
    session_.finish_list();
    session_.wait_idle();
    session_.command(word(Op::WritePort, port_bits(false, false)));
    link_->flush();
    lifecycle_.leave();  // a frame marks nothing: back to idle, not done
  } catch (const Aborted&) {
    report.stopped = true;  // abort() ran the stop sequence: red pointer and laser port off
  } catch (const std::exception& e) {
    try {
      fail_from(e);
    } catch (...) {
      report.packets = packets_ - packets_before;
      packets_ = packets_before;
      throw;
    }
  }
  report.packets = packets_ - packets_before;
  packets_ = packets_before;
  return report;
}

}  // namespace mark::lmc
