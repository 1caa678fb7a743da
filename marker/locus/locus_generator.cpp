#include "marker/locus/locus_generator.hpp"

#include <algorithm>
#include <cmath>

namespace mark {
namespace {

// Elements shorter than this are points: they take no time and produce no sample.

// Samples of one command given the ideal time so far (updated) and the samples already
// counted. Shared by the generator and count_samples so both agree to the sample.
std::uint32_t command_ticks(const Command& c, double tick_s, double& ideal_ticks,
                            std::uint64_t counted) {
  if (c.kind == CommandKind::dwell) {
    ideal_ticks += c.dwell_ticks;
    return c.dwell_ticks;
  }
  const double len = c.length_mm();
  if (len < kMinLength_mm) return 0;
  ideal_ticks += len / (c.speed_mm_s * tick_s);
  const auto end_tick = static_cast<std::int64_t>(std::llround(ideal_ticks));
  // At least one sample, so the element's end point is reached even when it is very short.
  return static_cast<std::uint32_t>(
      std::max<std::int64_t>(1, end_tick - static_cast<std::int64_t>(counted)));
}

inline void put(ScanSample& s, const Point& p, bool laser) {
  s.x_mm = static_cast<float>(p.x());
  s.y_mm = static_cast<float>(p.y());
  s.laser = laser;
  s.power = 255;
}

}  // namespace

LocusGenerator::LocusGenerator(std::span<const Command> commands, double tick_s)
    : commands_(commands), tick_s_(tick_s) {}

namespace {
bool plans_speeds(const Pen& pen) { return pen.lookahead || pen.feed_forward(); }
}  // namespace

LocusGenerator::LocusGenerator(const Plan& plan)
    : commands_(plan.commands), tick_s_(plan.pen.tick_s) {
  if (!plans_speeds(plan.pen)) return;
  InputShaper shaper = design_input_shaper(plan.pen);
  auto planned = std::make_unique<PlannedLocus>(plan.commands, plan.pen.tick_s,
                                                FeedForward{shaper.lag_s, shaper.inertia_s2});
  if (!shaper.active() || plan.commands.empty()) {
    profiled_ = std::move(planned);
    return;
  }
  const std::uint64_t samples = PlannedLocus::count_samples(plan.commands, plan.pen.tick_s);
  shaped_ = std::make_unique<ShapedLocus>(std::move(planned), std::move(shaper), samples,
                                          plan.commands.front().start(), plan.commands.back().end());
}

LocusGenerator::~LocusGenerator() = default;

std::uint64_t LocusGenerator::count_samples(const Plan& plan) {
  if (!plans_speeds(plan.pen)) return count_samples(plan.commands, plan.pen.tick_s);
  const std::uint64_t planned = PlannedLocus::count_samples(plan.commands, plan.pen.tick_s);
  return planned > 0 ? planned + design_input_shaper(plan.pen).tail_ticks() : 0;
}

std::uint64_t LocusGenerator::count_samples(std::span<const Command> commands, double tick_s) {
  double ideal = 0;
  std::uint64_t counted = 0;
  for (const Command& c : commands) counted += command_ticks(c, tick_s, ideal, counted);
  return counted;
}

bool LocusGenerator::advance() {
  while (next_ < commands_.size()) {
    const Command& c = commands_[next_++];
    const std::uint32_t n = command_ticks(c, tick_s_, ideal_ticks_, planned_);
    if (n == 0) continue;
    planned_ += n;
    kind_ = c.kind;
    laser_ = c.laser();
    step_ = 0;
    remaining_ = n;
    if (c.kind == CommandKind::dwell) {
      const Point p = c.start();
      hold_x_ = static_cast<float>(p.x());
      hold_y_ = static_cast<float>(p.y());
    } else {
      walker_.start(c.path, n);
    }
    return true;
  }
  return false;
}

std::size_t LocusGenerator::generate(ScanSample* out, std::size_t capacity) {
  if (profiled_ || shaped_) {
    const std::size_t n = shaped_ ? shaped_->generate(out, capacity) : profiled_->generate(out, capacity);
    emitted_ += n;
    return n;
  }
  std::size_t written = 0;
  while (written < capacity) {
    if (remaining_ == 0 && !advance()) break;
    // Interior steps of this element that fit, then its exact end point when it is reached.
    const std::uint32_t room = static_cast<std::uint32_t>(
        std::min<std::size_t>(capacity - written, remaining_));
    const std::uint32_t n = walker_.steps();
    const bool dwell = kind_ == CommandKind::dwell;
    const std::uint32_t interior = dwell ? room : std::min(room, remaining_ - 1);
    ScanSample* o = out + written;
    const bool laser = laser_;
    std::uint32_t j = step_;
    switch (kind_) {
      case CommandKind::dwell:
        for (std::uint32_t i = 0; i < interior; ++i) {
          o[i].x_mm = hold_x_;
          o[i].y_mm = hold_y_;
          o[i].laser = laser;
          o[i].power = 255;
        }
        break;
      case CommandKind::jump:
      case CommandKind::line:
        for (std::uint32_t i = 0; i < interior; ++i) put(o[i], walker_.line_step(++j), laser);
        break;
      case CommandKind::arc:
        for (std::uint32_t i = 0; i < interior; ++i) put(o[i], walker_.arc_next(), laser);
        j += interior;
        break;
      case CommandKind::ellipse:
        for (std::uint32_t i = 0; i < interior; ++i) put(o[i], walker_.ellipse_step(++j), laser);
        break;
    }
    std::uint32_t done_now = interior;
    if (!dwell && interior < room) {  // the end point lands on the element's last tick
      put(o[interior], walker_.end(), laser);
      ++done_now;
      j = n;
    }
    step_ = j;
    remaining_ -= done_now;
    written += done_now;
  }
  emitted_ += written;
  return written;
}

}  // namespace mark
