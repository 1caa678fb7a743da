#include "marker/job/timed_moves.hpp"

#include <algorithm>
#include <cmath>

#include "marker/locus/locus_generator.hpp"
#include "ringbuffer/laser_delay_line.hpp"

namespace mark {

TimedMoves::TimedMoves(double tick_s, std::vector<DeviceCommand>& out, TimedMoveLimits limits)
    : tick_s_(tick_s), limits_(limits), out_(out) {
  run_.reserve(limits_.max_ticks + 1);
}

// Whether the run with `next` appended is still one move: the same laser bit, not too long, and
// every inner sample within the tolerance of the evenly timed straight move to `next`.
bool TimedMoves::fits(const ScanSample& next) const {
  if (next.laser != run_[1].laser || run_.size() > limits_.max_ticks) return false;
  if (next.laser && (std::max<int>(power_max_, next.power) - std::min<int>(power_min_, next.power) >
                     limits_.power_spread))
    return false;
  const ScanSample& a = run_.front();
  const double n = static_cast<double>(run_.size());  // the move's ticks with `next`
  const double dx = (double(next.x_mm) - a.x_mm) / n, dy = (double(next.y_mm) - a.y_mm) / n;
  const double tol2 = limits_.tolerance_mm * limits_.tolerance_mm;
  for (std::size_t k = 1; k < run_.size(); ++k) {
    const double ex = a.x_mm + dx * double(k) - run_[k].x_mm, ey = a.y_mm + dy * double(k) - run_[k].y_mm;
    if (ex * ex + ey * ey > tol2) return false;
  }
  return true;
}

void TimedMoves::add(std::span<const ScanSample> block) {
  for (const ScanSample& s : block) {
    if (run_.size() >= 2 && !fits(s)) {
      emit();
      run_.erase(run_.begin(), run_.end() - 1);  // the next run starts where this one ends
      power_min_ = 255, power_max_ = 0;
    }
    if (!run_.empty()) power_min_ = std::min<int>(power_min_, s.power), power_max_ = std::max<int>(power_max_, s.power);
    run_.push_back(s);
  }
}

void TimedMoves::finish() {
  if (run_.size() >= 2) emit();
  run_.erase(run_.begin(), run_.end() - (run_.empty() ? 0 : 1));
  power_min_ = 255, power_max_ = 0;
}

void TimedMoves::emit() {
  const ScanSample &a = run_.front(), &b = run_.back();
  const std::size_t ticks = run_.size() - 1;
  const double n = static_cast<double>(ticks);
  const double dx = (double(b.x_mm) - a.x_mm) / n, dy = (double(b.y_mm) - a.y_mm) / n;
  for (std::size_t k = 1; k < ticks; ++k)
    max_error_mm_ = std::max(max_error_mm_, std::hypot(a.x_mm + dx * double(k) - run_[k].x_mm,
                                                       a.y_mm + dy * double(k) - run_[k].y_mm));
  const double length = std::hypot(dx, dy) * n;
  const double duration_s = n * tick_s_;
  const bool lit = run_[1].laser;
  double power = 0;
  for (std::size_t k = 1; k <= ticks; ++k) power += run_[k].power;
  // A run that stays put is a timed move too, not a dwell: the board holds it at the run's
  // power (a lit dwell would be at the pen's full power, where look-ahead has it at the slow
  // end of power ∝ speed).
  out_.push_back(DeviceCommand::timed_move(lit, b.x_mm, b.y_mm, length / duration_s, duration_s,
                                           power / (255.0 * n)));
}

DeviceProgram timed_program(const Plan& plan, const LaserSettings& laser,
                            const DeviceDescription& device) {
  DeviceProgram out;
  out.pen = device_pen(plan.pen, laser, DeviceLevel::commands);
  out.commands.push_back(DeviceCommand::select_pen(0));
  LocusGenerator locus(plan);
  LaserDelayLine delay(plan.pen.ticks(plan.pen.laser_on_delay_s), plan.pen.ticks(plan.pen.laser_off_delay_s));
  TimedMoves moves(plan.pen.tick_s, out.commands);
  std::vector<ScanSample> block(4096);
  ScanSample last;
  bool first = true;
  std::size_t checked = 0;
  const auto check_new = [&] {
    for (; checked < out.commands.size(); ++checked) {
      const DeviceCommand& c = out.commands[checked];
      if (c.op == DeviceOp::jump || c.op == DeviceOp::mark) check_in_field(device, c.x_mm, c.y_mm, checked);
    }
  };
  while (const std::size_t n = locus.generate(block.data(), block.size())) {
    const std::span<ScanSample> got(block.data(), n);
    delay.apply(got);
    if (first) {
      // The board starts wherever it is (the field centre after begin_job): travel to the
      // locus's first point first.
      out.commands.push_back(DeviceCommand::jump_to(got[0].x_mm, got[0].y_mm));
      first = false;
    }
    moves.add(got);
    last = got.back();
    check_new();
  }
  std::vector<ScanSample> tail;
  delay.flush(last, tail);
  moves.add(tail);
  moves.finish();
  check_new();
  return out;
}

}  // namespace mark
