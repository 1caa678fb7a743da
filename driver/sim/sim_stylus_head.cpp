#include "driver/sim/sim_stylus_head.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace mark {
namespace {

// The velocity noise's own stream from the same seed (a different sequence for every seed).
std::uint32_t velocity_seed(std::uint32_t seed) {
  std::seed_seq mixed{seed, 0x76656cu /* "vel" */};
  std::uint32_t out = 0;
  mixed.generate(&out, &out + 1);
  return out;
}

}  // namespace

SimStylusHead::SimStylusHead(SimStylusHeadOptions options)
    : options_(std::move(options)),
      noise_rng_(options_.noise_seed),
      velocity_noise_rng_(velocity_seed(options_.noise_seed)),
      lifecycle_("sim stylus head (" + mark::describe(options_.head) + ")") {
  validate(options_.head);
  if (options_.cells) validate(*options_.cells);
  if (!(options_.max_drive_um > 0)) throw std::invalid_argument("stylus head: amplifier range must be positive");
  if (!(options_.sense_noise_um >= 0)) throw std::invalid_argument("stylus head: sensing noise must be ≥ 0");
  if (!(options_.sense_velocity_noise_um_s >= 0))
    throw std::invalid_argument("stylus head: velocity sensing noise must be ≥ 0");
  for (const StylusMode& m : options_.head.modes) modes_.push_back({discretise(m), 0, 0});
}

DeviceDescription SimStylusHead::describe() const {
  DeviceDescription d;
  d.name = lifecycle_.device();
  d.level = DeviceLevel::samples;
  d.field_mm = 0;  // a stylus has no scan field: it moves in depth only
  d.tick_s = kStylusTick_s;
  return d;
}

void SimStylusHead::begin_job(const JobHeader& header) {
  lifecycle_.require(DeviceState::idle, "begin_job", "a job begins on an idle head (reset() it first)");
  const bool recording = options_.record_profile || options_.record_sense || options_.cells;
  if (recording && header.expected_samples == 0)
    throw std::invalid_argument("stylus head: job '" + header.name +
                                "' does not say how many samples it has (expected_samples); the "
                                "recordings are sized from it");
  if (recording && header.expected_samples > options_.max_record_samples)
    throw std::invalid_argument("stylus head: job '" + header.name + "' of " +
                                std::to_string(header.expected_samples) +
                                " samples is longer than the simulator records (" +
                                std::to_string(options_.max_record_samples) + " samples)");
  // Everything the drain thread will need, allocated now (a few samples of slack for the safe
  // samples the drain adds after the job's own).
  const std::uint64_t n = header.expected_samples + 4096;
  // A recording this job does not make gives its memory back; one it makes starts empty.
  for (auto* v : {&profile_, &sense_position_, &sense_velocity_}) std::vector<float>().swap(*v);
  if (options_.record_profile) profile_.reserve(n);
  if (options_.record_sense) {
    sense_position_.reserve(n);
    sense_velocity_.reserve(n);
  }
  meter_.reset();
  if (options_.cells) meter_.emplace(*options_.cells, cell_of_sample(n, options_.cells->cell_rate_hz) + 1);
  noise_rng_.seed(options_.noise_seed);
  noise_.reset();
  velocity_noise_rng_.seed(velocity_seed(options_.noise_seed));
  velocity_noise_.reset();
  for (Mode& m : modes_) m.x = m.v = 0;
  samples_ = 0;
  cutting_ = false;
  drive_peak_ = max_cut_ = 0;
  cut_samples_ = 0;
  lifecycle_.begin("begin_job");
  lifted_ = false;
  // An abort() between the two lines above found the head running and lifted it; keep it so.
  if (lifecycle_.abort_requested()) lifted_ = true;
}

DeviceReport SimStylusHead::end_job() {
  // A job the drain halted (a stop, an underrun) ends aborted unless a fault of the head's own
  // already failed it.
  const DeviceState s = lifecycle_.end();
  // The head retracts at the end of every job, whatever the last sample asked.
  lifted_ = true;
  cutting_ = false;
  if (meter_) meter_->finish();
  DeviceReport r;
  r.outcome = s;
  r.fault = lifecycle_.fault();
  r.samples_out = samples();
  r.device_time_s = device_time_s();
  r.figures = {{"samples", static_cast<double>(samples())},
               {"cut_samples", static_cast<double>(cut_samples_)},
               {"max_cut_um", max_cut_},
               {"drive_peak_um", drive_peak_},
               {"cells", meter_ ? static_cast<double>(meter_->cells().size()) : 0.0}};
  return r;
}

void SimStylusHead::abort() noexcept {
  lifecycle_.abort();
  lifted_ = true;
  cutting_ = false;
}

DeviceStatus SimStylusHead::status() const {
  DeviceStatus st = lifecycle_.snapshot();
  st.laser_on = cutting_.load();  // for a stylus: the diamond is in the copper
  st.progress = samples();
  return st;
}

void SimStylusHead::reset() { lifecycle_.reset(); }

void SimStylusHead::set_recording(bool profile, bool sense) {
  if (lifecycle_.state() == DeviceState::running)
    lifecycle_.refuse("set_recording", "what a job records is set between jobs");
  options_.record_profile = profile;
  options_.record_sense = sense;
}

const std::vector<CellFigures>& SimStylusHead::cells() const {
  static const std::vector<CellFigures> none;
  return meter_ ? meter_->cells() : none;
}

void SimStylusHead::fail(FaultCategory category, const std::string& message, std::uint64_t at) {
  halt();
  throw DeviceFaultError(lifecycle_.fail(DeviceFault{category, message, at}));
}

void SimStylusHead::check_block(std::span<const StylusSample> block) {
  const std::uint64_t base = samples();
  for (std::size_t i = 0; i < block.size(); ++i) {
    const float d = block[i].drive_um;
    if (std::isfinite(d) && std::abs(d) <= options_.max_drive_um) continue;
    char msg[200];
    std::snprintf(msg, sizeof msg,
                  "sim stylus head: sample %llu drives %.1f µm, outside the amplifier's ±%.0f µm; "
                  "head retracted",
                  static_cast<unsigned long long>(base + i), static_cast<double>(d), options_.max_drive_um);
    fail(FaultCategory::out_of_field, msg, base + i);
  }
}

// Before the cylinder engages, the head rests at the first drive of the job (no start-up ring).
void SimStylusHead::settle_at(double drive_um) {
  for (Mode& m : modes_) {
    m.x = m.step.gain * drive_um;
    m.v = 0;
  }
}

void SimStylusHead::write(std::span<const StylusSample> block) {
  if (lifecycle_.stopped() || lifecycle_.state() != DeviceState::running) {
    halt();
    lifecycle_.refuse("write", lifecycle_.state() == DeviceState::idle
                                   ? "samples go to a running job (begin_job)"
                                   : "the head is retracted until reset()");
  }
  check_block(block);
  if (block.empty()) return;
  if (samples() == 0) settle_at(block.front().drive_um);

  const double noise = options_.sense_noise_um, velocity_noise = options_.sense_velocity_noise_um_s;
  bool lifted = lifted_.load(std::memory_order_relaxed);
  double y = 0;
  for (const StylusSample& s : block) {
    if (s.lifted) lifted = true;
    const double u = s.drive_um;
    drive_peak_ = std::max(drive_peak_, std::abs(u));
    y = 0;
    double v = 0;
    for (Mode& m : modes_) {
      // s' = Φ s + (I − Φ)(g u, 0): the exact response to the drive held for this tick.
      const auto& p = m.step.phi;
      const double ex = m.x - m.step.gain * u;
      const double x1 = p[0] * ex + p[1] * m.v + m.step.gain * u;
      const double v1 = p[2] * ex + p[3] * m.v;
      m.x = x1;
      m.v = v1;
      y += x1;
      v += v1;
    }
    const float cut = lifted ? 0.0f : static_cast<float>(std::max(0.0, y));
    if (cut > 0) ++cut_samples_;
    max_cut_ = std::max(max_cut_, static_cast<double>(cut));
    if (options_.record_profile && profile_.size() < profile_.capacity()) profile_.push_back(cut);
    if (options_.record_sense && sense_position_.size() < sense_position_.capacity()) {
      sense_position_.push_back(static_cast<float>(y + (noise > 0 ? noise * noise_(noise_rng_) : 0.0)));
      sense_velocity_.push_back(static_cast<float>(
          v + (velocity_noise > 0 ? velocity_noise * velocity_noise_(velocity_noise_rng_) : 0.0)));
    }
    if (meter_) meter_->add(cut);
  }
  // Only ever set here: an abort() from another thread during this block must not be undone.
  if (lifted) lifted_.store(true, std::memory_order_relaxed);
  cutting_.store(!lifted_.load(std::memory_order_relaxed) && y > 0, std::memory_order_relaxed);
  samples_.fetch_add(block.size(), std::memory_order_relaxed);
}

void SimStylusHead::halt() noexcept {
  lifecycle_.halt();
  lifted_ = true;
  cutting_ = false;
}

}  // namespace mark
