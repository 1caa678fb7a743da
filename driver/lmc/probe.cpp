#include "driver/lmc/probe.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <limits>

#include "driver/lmc/job_encoder.hpp"
#include "driver/lmc/masked_link.hpp"

namespace mark::lmc {
namespace {

using Clock = std::chrono::steady_clock;

template <class... A>
std::string fmt(const char* f, A... a) {
  char buf[400];
  std::snprintf(buf, sizeof buf, f, a...);
  return buf;
}

// The probe's conversation: lists built from words, started, timed.
class Prober {
 public:
  Prober(LmcLink& link, const ProbeOptions& o, const std::function<void(const std::string&)>& progress)
      : masked_(link, o.laser_bit),
        session_(masked_, session_options(), abort_),
        options_(o),
        red_(std::uint16_t(1u << o.red_bit)),
        progress_(progress) {}

  static SessionOptions session_options() {
    SessionOptions s;
    s.poll_interval_s = 0.001;  // the measurements' resolution
    // The probe starts its lists itself (ExecuteList once queued, or when the buffer is full).
    s.execute_after_packets = std::numeric_limits<std::size_t>::max();
    s.grace_s = 2;
    return s;
  }

  BoardIdentity init() {
    InitParams p = options_.init;
    p.enable_laser = false;  // never needed: nothing fires
    const BoardIdentity id = session_.initialise(p, nullptr);
    session_.command(word(Op::WritePort, 0));
    return id;
  }

  // A list: ReadyMark, the red pointer on, `words`, EndOfList; sent with READY flow control,
  // started, timed from ExecuteList until BUSY clears.
  double run(const std::string& name, const std::vector<Word>& words, double estimate_s = 0) {
    session_.command(word(Op::ResetList));
    session_.begin_list();
    ListPacket p;
    const auto put = [&](const Word& w) {
      if (p.full()) {
        session_.send_packet(p, 0);
        p.clear();
      }
      p.push(w);
    };
    put(word(Op::ReadyMark));
    put(word(Op::ListWritePort, red_));
    for (const Word& w : words) put(w);
    put(word(Op::EndOfList));
    session_.send_packet(p, estimate_s);
    session_.finish_list();
    session_.wait_idle();
    const double t = std::chrono::duration<double>(Clock::now() - *session_.executed_at()).count();
    lists_.push_back({name, words.size() + 3, t});
    if (progress_) progress_(fmt("  %-34s %6zu words  %8.4f s", name.c_str(), words.size() + 3, t));
    return t;
  }

  // The median of `times` runs: a list of a few milliseconds is measured to the poll interval
  // plus whatever the host's scheduler adds, and the median drops a run the host was late for.
  double median(const std::string& name, const std::vector<Word>& words, int times = 3) {
    std::vector<double> t;
    for (int i = 0; i < times; ++i) t.push_back(run(name, words));
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
  }

  // How many packets the board takes before READY clears, none of them started.
  std::pair<std::size_t, bool> count_buffered() {
    session_.command(word(Op::ResetList));
    session_.begin_list();
    ListPacket p;
    p.push(word(Op::ReadyMark));
    while (!p.full()) p.push(word(Op::DelayTime, 1));
    std::size_t n = 0;
    bool capped = true;
    for (; n < kMaxProbePackets; ++n) {
      if ((session_.poll_status() & status::ready) == 0) {
        capped = false;
        break;
      }
      session_.send_packet(p, 0);
      p.clear();
      while (!p.full()) p.push(word(Op::DelayTime, 1));
    }
    session_.command(word(Op::StopExecute));
    session_.command(word(Op::ResetList));
    return {n, capped};
  }

  void close() {
    try {
      session_.command(word(Op::ResetList));
      session_.command(word(Op::WritePort, 0));
    } catch (...) {
    }
  }

  Session& session() { return session_; }
  std::uint16_t red() const { return red_; }
  std::vector<ProbeList> lists_;

 private:
  MaskedLink masked_;
  std::atomic<bool> abort_{false};
  Session session_;
  ProbeOptions options_;
  std::uint16_t red_;
  std::function<void(const std::string&)> progress_;
};

Word to(Op op, std::int32_t x, std::int32_t y, std::array<std::int32_t, 2>& at) {
  const double d = std::hypot(double(x - at[0]), double(y - at[1]));
  at = {x, y};
  return word(op, std::uint16_t(x), std::uint16_t(y), 0, distance_word(d));
}

}  // namespace

ProbeReport probe_board(LmcLink& link, const ProbeOptions& o, const std::function<void(const std::string&)>& progress) {
  ProbeReport r;
  r.link = link.name();
  Prober pr(link, o, progress);
  r.identity = pr.init();
  constexpr std::int32_t c = 0x8000;
  std::array<std::int32_t, 2> at{c, c};
  const auto home = [&] { return to(Op::JumpTo, c, c, at); };

  // The host's own share of every measurement: an empty list.
  r.latency_s = pr.median("empty list", {});

  // 1. The jump delay the board holds: 800 one-tick jumps with no JumpDelay, then with 0. First,
  //    before anything of the probe sets one; the lists without a JumpDelay set nothing, so they
  //    too can be taken three times and their median kept (one run the host was late for adds
  //    tens of milliseconds, tens of µs a jump).
  {
    constexpr int n = 800;
    const auto jumps = [&](bool set) {
      std::vector<Word> w{word(Op::JumpSpeed, 10000)};
      if (set) w.push_back(word(Op::JumpDelay, 0, 0));
      at = {c, c};
      w.push_back(home());
      for (int i = 0; i < n; ++i) w.push_back(to(Op::JumpTo, c + (i % 2 ? 0 : 100), c, at));
      return w;
    };
    const double held = pr.median("jumps, no JumpDelay sent", jumps(false));
    const double zero = pr.median("jumps, JumpDelay 0", jumps(true));
    r.held_jump_delay_us = std::max(0.0, (held - zero) / n * 1e6);
  }

  // 2. PolygonDelay: word 300 at 100 right angles and at 100 straight-on junctions, each against
  //    the same list with word 0. Marks of 100 units at 100 units a tick.
  {
    constexpr int n = 100;
    constexpr std::uint16_t kWord = 300;
    const auto marks = [&](std::uint16_t delay, bool corners) {
      std::vector<Word> w{word(Op::JumpSpeed, 10000), word(Op::MarkSpeed, 10000), word(Op::JumpDelay, 0, 0),
                          word(Op::LaserOnDelay, 0, 0), word(Op::LaserOffDelay, 0, 0),
                          word(Op::PolygonDelay, delay, 0)};
      at = {c, c};
      w.push_back(to(Op::JumpTo, c - 10000, c - 10000, at));
      std::int32_t x = c - 10000, y = c - 10000;
      for (int i = 0; i <= n; ++i) {
        if (corners) (i % 2 ? y : x) += 100;  // a staircase: every junction a right angle
        else x += 100;                       // a straight line
        w.push_back(to(Op::MarkTo, x, y, at));
      }
      w.push_back(home());
      return w;
    };
    const double c0 = pr.median("right angles, PolygonDelay 0", marks(0, true));
    const double c1 = pr.median("right angles, PolygonDelay 300", marks(kWord, true));
    const double s0 = pr.median("straight on, PolygonDelay 0", marks(0, false));
    const double s1 = pr.median("straight on, PolygonDelay 300", marks(kWord, false));
    r.polygon_word = kWord;
    r.polygon_corner_us = (c1 - c0) / n * 1e6;
    r.polygon_straight_us = (s1 - s0) / n * 1e6;
    // 300 in µs is 300 µs, in 10 µs units 3000 µs: the boundary is the geometric middle.
    const double us = kWord, ten_us = 10.0 * kWord, middle = std::sqrt(us * ten_us);
    if (r.polygon_corner_us > us / 3 && r.polygon_corner_us < middle) r.polygon_unit = "us";
    else if (r.polygon_corner_us >= middle && r.polygon_corner_us < 3 * ten_us) r.polygon_unit = "10us";
    else r.polygon_unit = "unclear";
    if (r.polygon_unit != "unclear") r.polygon_scaled = r.polygon_straight_us < 0.5 * r.polygon_corner_us;
  }

  // 3. A JumpTo after a mark: 100 mark-then-jump pairs with a laser-off delay of 2000 µs, and 0.
  {
    constexpr int n = 100;
    const auto pairs = [&](std::uint16_t off_us) {
      std::vector<Word> w{word(Op::JumpSpeed, 10000), word(Op::MarkSpeed, 10000), word(Op::JumpDelay, 0, 0),
                          word(Op::LaserOnDelay, 0, 0), word(Op::LaserOffDelay, off_us, 0),
                          word(Op::PolygonDelay, 0, 0)};
      at = {c, c};
      w.push_back(to(Op::JumpTo, c - 10000, c, at));
      for (int i = 0; i < n; ++i) {
        w.push_back(to(Op::MarkTo, at[0] + 100, c, at));
        w.push_back(to(Op::JumpTo, at[0] + 100, c, at));
      }
      w.push_back(home());
      return w;
    };
    const double off0 = pr.median("mark + jump, laser-off delay 0", pairs(0));
    const double off2 = pr.median("mark + jump, laser-off delay 2000 us", pairs(2000));
    r.off_delay_wait_us = (off2 - off0) / n * 1e6;
    r.jump_waits = r.off_delay_wait_us > 1000;
  }

  // 4. Packets buffered before READY clears (nothing executes).
  std::tie(r.buffered_packets, r.buffered_capped) = pr.count_buffered();

  // Lists longer than the board's buffer stream while it runs: every packet of these holds at
  // least 12 ms of board time, so a host that refills it a few milliseconds late starves nothing.

  // 5. DelayTime: 12000 × 20 µs against 1200 × 200 µs, 240 ms each: what a word costs on top
  //    of its own time, from 10800 words' difference (a tick each would add 108 ms).
  {
    const double many = pr.median("12000 × DelayTime 20 us", std::vector<Word>(12000, word(Op::DelayTime, 2)));
    const double few = pr.median("1200 × DelayTime 200 us", std::vector<Word>(1200, word(Op::DelayTime, 20)));
    r.delay_time_extra_us = (many - few) / 10800 * 1e6;
    r.delay_time_extra_tick = r.delay_time_extra_us > 5;
  }

  // 6. Parameter words: 6000 × (DelayTime 50 µs, MarkSpeed) against 6000 × DelayTime 50 µs
  //    (a tick each would add 60 ms).
  {
    std::vector<Word> with, without(6000, word(Op::DelayTime, 5));
    for (int i = 0; i < 6000; ++i) {
      with.push_back(word(Op::DelayTime, 5));
      with.push_back(word(Op::MarkSpeed, std::uint16_t(1000 + i % 2)));
    }
    const double p1 = pr.median("6000 × (DelayTime, MarkSpeed)", with);
    const double p0 = pr.median("6000 × DelayTime 50 us", without);
    r.parameter_word_us = (p1 - p0) / 6000 * 1e6;
    r.parameter_word_tick = r.parameter_word_us > 5;
  }

  // 7. Tick rounding: 3000 jumps of 52 units at 5 units a tick (10.4 ticks each) against 3000 of
  //    50 units (10 ticks): whole ticks rounded up add 1 tick a jump, the exact time 0.4, whole
  //    ticks rounded to the nearest none.
  {
    const auto jumps = [&](std::int32_t length) {
      std::vector<Word> w{word(Op::JumpSpeed, 500), word(Op::JumpDelay, 0, 0)};
      at = {c, c};
      for (int i = 0; i < 3000; ++i) w.push_back(to(Op::JumpTo, c + (i % 2 ? 0 : length), c, at));
      w.push_back(home());
      return w;
    };
    const double a = pr.median("3000 jumps of 10.4 ticks", jumps(52));
    const double b = pr.median("3000 jumps of 10 ticks", jumps(50));
    r.move_ticks_exact = 10.4;
    r.move_ticks_measured = 10 + (a - b) / 3000 / kTick_s;
    const double extra = r.move_ticks_measured - 10;
    r.move_rounding = extra > 0.75 ? "whole (up)" : extra > 0.2 && extra < 0.6 ? "exact" : extra < 0.15 ? "nearest" : "unclear";
  }

  // 8. A list as a job makes it (a serpentine of 0.2 mm marks at 2000 mm/s with a travel jump
  //    every 20, laser delays 100 µs), encoded by the job encoder at 0 % power, against the
  //    encoder's own estimate.
  {
    const FieldUnits units(o.field_mm, o.axes, o.polygon_delay_unit);
    DevicePen pen;
    pen.mark_speed_mm_s = 2000;
    pen.jump_speed_mm_s = 4000;
    pen.laser_on_delay_s = pen.laser_off_delay_s = 100e-6;
    pen.laser.source = o.source;
    pen.laser.power_pct = 0;
    pen.laser.frequency_khz = std::clamp(30.0, limits_of(o.source).min_frequency_khz, limits_of(o.source).max_frequency_khz);
    const BoardPen bp = encode_pen(pen, 0, units);
    std::vector<Word> words;
    double estimate = 0;
    JobEncoder enc(units, [&](const ListPacket& p, const PacketInfo& info) {
      for (std::size_t i = 0; i < p.used(); ++i) words.push_back(load(p.bytes().data() + 12 * i));
      estimate += info.estimated_s;
    });
    enc.start_list(0, pr.red());
    enc.apply_pen(bp);
    constexpr int n = 2000;
    enc.add(DeviceCommand::jump_to(-10, 0), 0);
    for (int i = 1; i <= n; ++i) {
      const int row = i / 50, col = i % 50;
      const double x = -10 + 0.2 * (row % 2 ? 50 - col : col), y = 0.1 * row + (i % 2 ? 0.05 : 0);
      enc.add(i % 20 == 0 ? DeviceCommand::jump_to(x, y) : DeviceCommand::mark_to(x, y), std::uint64_t(i));
    }
    enc.finish(n + 1);
    // The encoder's list without its ReadyMark, port word and EndOfList, which run() adds.
    std::vector<Word> body;
    for (const Word& w : words)
      if (w.opcode() != std::uint16_t(Op::ReadyMark) && w.opcode() != std::uint16_t(Op::ListWritePort) &&
          w.opcode() != std::uint16_t(Op::EndOfList))
        body.push_back(w);
    r.list_moves = enc.figures().moves;
    r.list_estimated_s = estimate;
    r.list_measured_s = pr.run("a job's list of 2001 moves", body, estimate) - r.latency_s;
  }
  pr.close();
  r.lists = pr.lists_;

  // What it settles.
  auto& out = r.conclusions;
  r.polygon_units_option = r.polygon_unit == "10us" ? "10us" : "us";
  if (r.polygon_unit == "unclear")
    out.push_back(fmt("PolygonDelay: a word of %d held %.0f µs per right angle, neither %d µs (µs) nor %d µs "
                      "(10 µs units): run the probe again, and report it",
                      r.polygon_word, r.polygon_corner_us, r.polygon_word, 10 * r.polygon_word));
  else
    out.push_back(fmt("PolygonDelay is read in %s: a word of %d held %.0f µs per right angle; give "
                      "--polygon-delay-units %s%s",
                      r.polygon_unit == "us" ? "µs" : "10 µs units", r.polygon_word, r.polygon_corner_us,
                      r.polygon_units_option.c_str(), r.polygon_units_option == "us" ? " (the default)" : ""));
  if (r.polygon_scaled)
    out.push_back(*r.polygon_scaled
                      ? fmt("the polygon delay is scaled by the turn: %.0f µs at a straight-on junction, as the host's "
                            "estimate and the emulated board assume (1 − cos φ)",
                            r.polygon_straight_us)
                      : fmt("the polygon delay is NOT scaled by the turn: %.0f µs at a straight-on junction against %.0f µs "
                            "at a right angle; the host's estimate of corners is low on this board",
                            r.polygon_straight_us, r.polygon_corner_us));
  out.push_back(r.jump_waits
                    ? fmt("a JumpTo after a mark waits out the laser-off delay (%.0f µs per jump for 2000 µs): with "
                          "--corner blanking the run-out stops at the stroke's end with the laser on for that delay; "
                          "use a laser-off delay of 0 with blanking, or --corner delays",
                          r.off_delay_wait_us)
                    : fmt("a JumpTo after a mark does not wait for the laser-off delay (%.0f µs per jump for 2000 µs): "
                          "blanking run-outs run through it, as planned",
                          r.off_delay_wait_us));
  out.push_back(r.buffered_capped
                    ? fmt("the board took %.0f packets and stayed READY: it buffers at least that many", double(r.buffered_packets))
                    : fmt("the board buffers %.0f packets (%.0f list words) before READY clears", double(r.buffered_packets),
                          double(r.buffered_packets * kCommandsPerPacket)));
  out.push_back(r.delay_time_extra_tick
                    ? fmt("DelayTime takes %.1f µs more than its own time per word (a tick of its own)", r.delay_time_extra_us)
                    : fmt("DelayTime takes its own time (%.1f µs more per word)", r.delay_time_extra_us));
  out.push_back(r.parameter_word_tick
                    ? fmt("a parameter word takes %.1f µs (a tick) of list time: use --word-ticks, so look-ahead and "
                          "feed-forward's timed moves give those ticks back",
                          r.parameter_word_us)
                    : fmt("parameter words take no list time (%.1f µs per word)", r.parameter_word_us));
  out.push_back(fmt("a move of %.1f ticks took %.2f: ", r.move_ticks_exact, r.move_ticks_measured) +
                (r.move_rounding == "whole (up)" ? "whole ticks, rounded up"
                 : r.move_rounding == "exact"    ? "its exact time, the fraction carried"
                 : r.move_rounding == "nearest"  ? "whole ticks, rounded to the nearest"
                                                 : "none of whole, exact or nearest"));
  if (r.held_jump_delay_us > kHeldJumpDelayNoise_us)
    out.push_back(fmt("the board held a jump delay of %.0f µs from before the probe (power-on or another program): "
                      "every list this driver sends sets its own",
                      r.held_jump_delay_us));
  else
    out.push_back(fmt("the board held no jump delay before the probe set one (%.1f µs per jump)", r.held_jump_delay_us));
  out.push_back(fmt("a job's list of %.0f moves took %.3f s against the host's estimate of %.3f s", double(r.list_moves),
                    r.list_measured_s, r.list_estimated_s) +
                fmt(" (× %.3f)", r.list_estimated_s > 0 ? r.list_measured_s / r.list_estimated_s : 0));
  return r;
}

}  // namespace mark::lmc
