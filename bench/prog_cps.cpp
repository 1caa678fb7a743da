// Characters per second, SCANLAB's method (galvo.md §5): the 62 characters A–Z a–z 0–9 in the
// built-in font at 1 mm cap height, marked on each simulated head with each strategy. For each
// quality class (driver/sim/quality_class.hpp) the search finds the highest characters per second
// that still meets the class, over every parameter the strategy has — the marking speed and its
// delays, run-ins, rates and thresholds — and prints the parameters it found as `marker mark`
// options. Every trial is a virtual-time run of the whole job: layout, plan, locus, line memory,
// drain with the laser delay line, simulated scanner, quality figures.
//
// The planner never reads the simulated head's parameters: each head is identified first
// (`marker head identify`: its response to a test pattern, fitted), and the strategies plan with
// that fitted profile — in the model-error rows with its lag deliberately off by ±10 %, or with
// a first-order model of a second-order head.
//
// The rows on the exact head (the simulated plant is the very model identified, noise-free) are
// an upper bound: a real head is never its model. The robust rows (plant "set") must hold their
// class on every plant of a set at once with one pen — the exact one, the servo's lag ±10 %, a
// 10 µs servo dead time, a 10 kHz mirror resonance, 1 µm of position noise, speeding-up
// acceleration falling to nothing at 12 m/s (back-EMF) and a drive that trips above 40 % rms
// acceleration over 20 ms (issue 24; the effects are driver/sim/plant.hpp's, which the planner
// does not model). The "picture per plant" rows mark on the same set, but each plant is planned
// with the profile fitted from a picture of its own lag test pattern (`head test-pattern`, then
// `head identify --from-image`): what a user who identifies the head in front of them gets, the
// lag error of a datasheet gone and the effects the fit cannot see left.
//
// The strategy none+ff+zv is none+ff through an input shaper (marker/plan/input_shaper.hpp):
// told the set's 10 kHz mirror resonance in the exact and datasheet rows, and in the picture-per-
// plant row shaped against the resonance each plant's picture showed (none where it showed none;
// none+ff's picture row does the same, from its own starting points). SL10 only, in the exact
// row and the set's rows.
//
// Every pen gets the pulse frequency its speed needs for the spots of consecutive pulses to
// overlap (the quality classes see gaps between them), within the laser source's range
// (`--source`, default fiber); a speed that would need more than the source runs is not
// reachable with that source.
//
//   cps [--short] [--json] [--head NAME] [--strategy NAME] [--workers N] [--source NAME] [--max-frequency KHZ]
//       [--device sim|lmc-emulated[:VARIANT]]
//   cps --speed MM_S [--head NAME] [--strategy NAME] [--text T] [--font F]
// --speed evaluates one speed with each strategy's default parameters instead of searching.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "base/error.hpp"
#include "driver/device_error.hpp"
#include "driver/laser_source.hpp"
#include "driver/sim/head_model.hpp"
#include "driver/sim/quality_class.hpp"
#include "fonts/catalog.hpp"
#include "driver/lmc/lmc_spec.hpp"
#include "marker/cli/device_factory.hpp"
#include "marker/cli/emulated_lmc_device.hpp"
#include "marker/cli/lmc_options.hpp"
#include "marker/cli/pen_options.hpp"
#include "marker/cli/plant_option.hpp"
#include "marker/head/head_fit.hpp"
#include "marker/head/lag_photo.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/intended_strokes.hpp"
#include "marker/job/job.hpp"
#include "marker/job/sim_evaluator.hpp"
#include "marker/locus/locus_generator.hpp"
#include "marker/plan/stroke.hpp"

namespace {

using namespace mark;

constexpr const char* kCharacters = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
// SCANLAB's typical marking speed for small characters on 10 mm heads (dynamics.md §1.2): the
// ink-only bound marks nothing but ink, at this speed, with no jumps or corners.
constexpr double kInkSpeed_mm_s = 3500;
constexpr double kTick_s = 10e-6;
constexpr double kLaserRise_s = 20e-6;  // the laser-rise rows: two ticks
// Pulses: spots this share of a diameter apart at the marking speed (20 % overlap: margin for a
// beam that runs faster than its command, which feed-forward's corners do), and never slower
// than the sources' usual 30 kHz (LaserSettings' default), so slow rows mark as they did.
constexpr double kPulsePitchShare = 0.8;
constexpr double kBaseFrequency_khz = 30;
constexpr int kFrequencyRounds = 3;  // raises of the frequency after a mark showed a gap

// A strategy: a corner strategy, whether speeds are planned and the head fed forward, and the
// parameters the search may change (x[0] is always the marking speed).
struct Param {
  const char* name;
  double initial, lo, hi;
  bool zero_ok;  // the search may set it to 0 (below lo)
};

struct Strategy {
  std::string name;
  CornerStrategy corner;
  bool lookahead, feed_forward;
  std::vector<Param> params;
  // Further starting points besides the parameters' initial values (a pattern search finds a
  // local optimum; gentle and brisk starts find the robust and the fast one).
  std::vector<std::vector<double>> starts = {};
  // Input shaping against this mirror resonance (0: none): the robust set's 10 kHz, which the
  // rows planned from the datasheet or the step response are told; the picture-per-plant rows
  // shape against what each plant's picture showed (marker/head/ring_fit.hpp), or not at all.
  double shaper_hz = 0;
};

const Param kSpeed{"speed_mm_s", 300, 20, 20000, false};
// The mirror resonance of the robust set (kRobustPlants).
constexpr double kRobustResonance_hz = 10000;

std::vector<Strategy> all_strategies() {
  const Param accel{"accel_share", 0.3, 0.005, 0.95, false};
  const Param curve{"curve_accel_share", 0.3, 0.005, 0.95, false};
  const Param jump{"jump_accel_share", 0.8, 0.01, 0.95, false};
  return {
      {"blanking", CornerStrategy::blanking, false, false,
       {{"speed_mm_s", 150, 20, 20000, false},
        {"min_run_in", 1.0, 0.1, 10, true},
        {"run_out", 1.0, 0.1, 5, true},
        {"settle_um", 1.0, 0.05, 20, false},
        {"blank_angle_deg", 8, 1, 90, true}}},
      {"delays", CornerStrategy::delays, false, false,
       {{"speed_mm_s", 60, 20, 20000, false},
        {"laser_on", 0.6, 0.05, 5, true},
        {"laser_off", 1.2, 0.05, 5, true},
        {"jump", 2.0, 0.1, 10, true},
        {"mark", 1.0, 0.1, 5, true},
        {"polygon", 0.5, 0.05, 5, true},
        {"jump_settle_um", 1.0, 0.05, 20, true}}},
      {"none", CornerStrategy::none, false, false, {{"speed_mm_s", 40, 20, 20000, false}}},
      {"none+la", CornerStrategy::none, true, false, {kSpeed, accel, curve, jump},
       {{150, 0.05, 0.05, 0.3}, {600, 0.3, 0.3, 0.8}}},
      {"none+ff", CornerStrategy::none, true, true,
       {{"speed_mm_s", 1000, 20, 20000, false}, accel, curve, jump,
        {"min_lit_speed_share", 0.03, 0.005, 0.5, true}},
       {{2000, 0.9, 0.9, 0.9, 0.03}, {2000, 0.1, 0.05, 0.3, 0.15}, {1000, 0.05, 0.05, 0.3, 0.1}}},
      {"none+ff+zv", CornerStrategy::none, true, true,
       {{"speed_mm_s", 1000, 20, 20000, false}, accel, curve, jump,
        {"min_lit_speed_share", 0.03, 0.005, 0.5, true}},
       {{5000, 0.27, 0.27, 0.36, 0.1}, {2000, 0.1, 0.05, 0.3, 0.15}},
       kRobustResonance_hz},
      {"blanking+ff", CornerStrategy::blanking, true, true,
       {kSpeed, accel, curve, jump, {"run_in", 1.0, 0.1, 10, true}, {"run_out", 1.0, 0.1, 10, true}},
       {{1000, 0.3, 0.3, 0.8, 2, 1}, {300, 0.05, 0.05, 0.3, 3, 1}}},
  };
}

// The pen for a point of a strategy's parameter space, planned with `model`.
Pen pen_at(const Strategy& s, const std::vector<double>& x, const HeadProfile& model) {
  PenRules r;
  r.lookahead = s.lookahead;
  r.feed_forward = s.feed_forward;
  auto get = [&](const char* name) {
    for (std::size_t i = 0; i < s.params.size(); ++i)
      if (std::string(s.params[i].name) == name) return std::optional<double>(x[i]);
    return std::optional<double>();
  };
  if (auto v = get("min_run_in")) r.min_run_in = *v;
  if (auto v = get("run_out")) r.run_out = *v;
  if (auto v = get("run_in")) r.run_in = *v;
  if (auto v = get("settle_um")) r.settle_um = *v;
  if (auto v = get("blank_angle_deg")) r.blank_angle_deg = *v;
  if (auto v = get("laser_on")) r.laser_on = *v;
  if (auto v = get("laser_off")) r.laser_off = *v;
  if (auto v = get("jump")) r.jump = *v;
  if (auto v = get("mark")) r.mark = *v;
  if (auto v = get("polygon")) r.polygon = *v;
  if (auto v = get("jump_settle_um")) r.jump_settle_um = *v;
  if (auto v = get("accel_share")) r.accel_share = *v;
  if (auto v = get("curve_accel_share")) r.curve_accel_share = *v;
  if (auto v = get("jump_accel_share")) r.jump_accel_share = *v;
  if (auto v = get("min_lit_speed_share")) r.min_lit_speed_share = *v;
  Pen pen = pen_for_profile(model, s.corner, x[0], kTick_s, r);
  // A profile fitted from a picture shapes against the resonance the picture showed, or none
  // (pen_for_profile); the others are told the set's.
  if (s.shaper_hz > 0 && model.source != "image") pen.shaper_hz = s.shaper_hz;
  return pen;
}

// The text laid out once; its intended strokes indexed once for every trial.
struct Workload {
  std::string text = kCharacters;
  std::shared_ptr<const StrokeFont> font;
  LayoutOptions layout;
  std::unique_ptr<QualityReference> reference;
  double characters = 62;
  double ink_mm = 0;

  Workload(std::string t, const std::string& font_name) : text(std::move(t)) {
    font = open_font(font_name);
    layout.height_mm = 1.0;
    layout.align = Align::center;
    layout.base = Point(0, 0.5);
    const Figure figure = layout_text(text, *font, layout);
    reference = std::make_unique<QualityReference>(intended_polylines(figure));
    for (const Stroke& s : strokes_of(figure)) ink_mm += s.length_mm();
    characters = 0;
    for (char c : text) characters += c != ' ' && c != '\n';
  }
  double ink_bound_cps() const { return characters / (ink_mm / kInkSpeed_mm_s); }
};

// The simulated head a row marks on: the preset, its servo model, the laser's rise time.
struct RealHead {
  HeadModel model;
  double laser_rise_s = 0;
  std::string head_model() const { return model.second_order ? "second" : "first"; }
};

struct Trial {
  double cps = 0;
  double mark_time_s = 0;
  Quality quality;
  double frequency_khz = 0;  // the pen's pulse frequency
};

// The laser source the rows mark with (--source).
LaserSource g_source = LaserSource::fiber;
// --material-speed: dose sufficiency against a material that a single line at full power marks
// one beam diameter wide at this speed, the same for every pen (0: each pen's own power / speed).
double g_material_speed_mm_s = 0;

// --max-frequency: a source that tops out below its kind's range (a 100 kHz Q-switched fiber
// laser: --source fiber --max-frequency 100). 0: the kind's own top.
double g_max_frequency_khz = 0;

// The top of the rows' source.
double source_max_khz() {
  const double top = limits_of(g_source).max_frequency_khz;
  return g_max_frequency_khz > 0 ? std::min(top, g_max_frequency_khz) : top;
}

// Whole kHz within the source's range.
double within_source(double khz) {
  return std::clamp(std::ceil(khz - 1e-9), limits_of(g_source).min_frequency_khz, source_max_khz());
}

// The frequency a pen at `speed` starts from: spots kPulsePitchShare of a diameter apart.
double frequency_for(double speed_mm_s, const RealHead& head) {
  const double pitch_mm = kPulsePitchShare * head.model.spot_diameter_um * 1e-3;
  return within_source(std::max(kBaseFrequency_khz, speed_mm_s / pitch_mm * 1e-3));
}

// After a mark whose pulses left a gap (the beam ran faster than the pen somewhere): the
// frequency that puts the widest spacing seen at kPulsePitchShare. 0 when the source cannot
// go higher, or there was no gap.
double raised_frequency(double khz, const Quality& q) {
  if (!(q.pulse_gap_max_um > 0) || q.spot_diameter_um <= 0) return 0;
  const double spacing = q.pulse_gap_max_um + q.spot_diameter_um;
  const double raised = within_source(khz * spacing / (kPulsePitchShare * q.spot_diameter_um));
  return raised > khz ? raised : 0;
}

JobSpec spec_for(const Workload& w, const RealHead& head, const Pen& pen, double frequency_khz = 0) {
  JobSpec spec;
  spec.laser.source = g_source;
  spec.laser.frequency_khz = frequency_khz > 0 ? frequency_khz : frequency_for(pen.mark_speed_mm_s, head);
  spec.text = w.text;
  spec.font = w.font;
  spec.layout = w.layout;
  spec.head = head.model;
  spec.pen = pen;
  if (g_material_speed_mm_s > 0) {
    spec.verify.response.reference_speed_mm_s = g_material_speed_mm_s;  // reference width: one beam
    spec.verify.dose_vs_material = true;
  }
  return spec;
}

// The plants of the robust rows, as `--plant` takes them ("": the exact model).
// The back-EMF and thermal entries are the harsher of docs/speed.md's measured rows: no datasheet
// here gives a preset's figures, so the set asks for a margin a real drive is likely to leave.
const std::vector<std::string> kRobustPlants = {"",
                                                "tau_scale=0.9",
                                                "tau_scale=1.1",
                                                "dead_us=10",
                                                "resonance_hz=10000",  // kRobustResonance_hz
                                                "noise_um=1",
                                                "backemf_speed=12000",
                                                "rms_accel_pct=40,thermal_tau_s=0.02"};

// --device: where every trial marks. "sim", the simulated scanner; "lmc-emulated[:VARIANT]", the
// emulated LMC board (the real driver's packets, the board's own clock and units, feed-forward
// as timed moves) driving that scanner, in virtual time: a search on the board itself.
std::string g_device = "sim";

// The emulated board's job on the simulated scanner; its device time is the scanner's (the
// board's clock), not the host's wall time.
JobResult mark_on_board(const JobSpec& spec, const QualityReference* reference, const RealHead& head,
                        const Plant& plant) {
  cli::SimSettings sim;
  sim.laser_rise_s = head.laser_rise_s;
  sim.plant = plant;
  sim.virtual_time = true;
  const cli::OpenedDevice opened = cli::open_device(g_device, spec, sim, cli::LmcArgs{});
  auto& board = dynamic_cast<cli::EmulatedLmcDevice&>(*opened.device);
  SimEvaluator evaluator(board.scanner(), reference);
  JobOptions options;
  options.virtual_time = true;
  options.evaluator = &evaluator;
  JobResult r = run_job(spec, options, board);
  for (const auto& [key, value] : r.device.figures)
    if (key == "scanner_device_time_s") r.mark_time_s = value;
  return r;
}

Trial mark_with(const Workload& w, const RealHead& head, const Pen& pen, const Plant& plant = {},
                double frequency_khz = 0) {
  const JobSpec spec = spec_for(w, head, pen, frequency_khz);
  JobResult r;
  if (g_device == "sim") {
    JobOptions options;
    options.virtual_time = true;
    SimScannerOptions sim = simulator_options(spec);
    sim.laser_rise_s = head.laser_rise_s;
    sim.plant = plant;
    SimScanner scanner(sim);
    r = run_job_simulated(spec, options, scanner, w.reference.get());
  } else {
    r = mark_on_board(spec, w.reference.get(), head, plant);
  }
  // A board that stopped early (a drive trip, a fault) marked the part badly: its quality says so.
  return {w.characters / r.mark_time_s, r.mark_time_s, *r.quality, spec.laser.frequency_khz};
}

// The job's device time without running it (locus samples plus the laser delay line's tail):
// a candidate that cannot beat the best so far is never simulated.
double predicted_cps(const Workload& w, const RealHead& head, const Pen& pen) {
  const CompiledJob job = compile_job(spec_for(w, head, pen));
  const double samples = static_cast<double>(LocusGenerator::count_samples(job.plan)) +
                         static_cast<double>(job.laser_off_ticks);
  return w.characters / (samples * pen.tick_s);
}

struct Row {
  std::string head_name;
  RealHead head;
  HeadProfile model;        // the planner's model as identified
  // The planner's lag errors against the identified one that the row must hold at, each a
  // separate mark: {e} for a model-error row, {0, −0.1, +0.1} for the robust row (one set of
  // parameters that works whichever way the model is off). The first is the reported pen's.
  std::vector<double> errors = {0.0};
  // The plants (`--plant` texts) every error is marked on: {""} the exact model, or the robust set.
  std::vector<std::string> plants = {""};
  // Per plant, the profile fitted from a picture of its own test pattern; empty: `model` for all.
  std::vector<HeadProfile> plant_models;
  std::string model_note;   // "" or e.g. "first-order model"
  const Strategy* strategy = nullptr;
  const QualityLimits* level = nullptr;
  std::size_t seed_row = SIZE_MAX;  // the good row starts from its high row's result
  // Results.
  std::optional<Trial> trial;
  std::vector<double> x;
  Pen pen;
  int trials = 0;
  double search_s = 0;  // wall time of the row's search
};

class Search {
 public:
  Search(const Workload& w, Row& row, bool quick) : w_(w), row_(row), quick_(quick) {
    for (const std::string& p : row.plants) plants_.push_back(cli::parse_plant_option(p));
  }

  void run(std::optional<std::vector<double>> start) {
    const Strategy& s = *row_.strategy;
    std::vector<double> x;
    if (start) {
      x = *start;
    } else {
      // The best feasible of the starting points, each made slower and gentler until the class
      // is met (or given up on).
      std::vector<std::vector<double>> starts = {initial(s)};
      starts.insert(starts.end(), s.starts.begin(), s.starts.end());
      for (std::vector<double> y : starts) {
        for (int i = 0; i < 8 && !feasible(y); ++i)
          for (std::size_t j = 0; j < y.size(); ++j)
            if (j == 0 || std::string(s.params[j].name).find("share") != std::string::npos)
              y[j] = std::max(s.params[j].lo, y[j] / 2);
      }
      if (!row_.trial) return;
      x = row_.x;
    }
    // Pattern search in log space with shrinking steps: move one parameter at a time, keep
    // any move that raises the characters per second and still meets the class.
    const std::vector<double> steps =
        quick_ ? std::vector<double>{2.0, 1.41} : std::vector<double>{2.0, 1.41, 1.19, 1.09};
    for (double f : steps) {
      for (bool improved = true; improved;) {
        improved = false;
        for (std::size_t j = 0; j < x.size(); ++j) {
          for (int dir : {1, -1}) {
            std::vector<double> y = x;
            y[j] = moved(s.params[j], x[j], f, dir);
            if (y[j] == x[j] || !better(y)) continue;
            x = y;
            improved = true;
            break;
          }
        }
      }
    }
  }

 private:
  static std::vector<double> initial(const Strategy& s) {
    std::vector<double> x;
    for (const Param& p : s.params) x.push_back(p.initial);
    return x;
  }
  static double moved(const Param& p, double v, double f, int dir) {
    if (v == 0) return dir > 0 ? p.lo : 0.0;
    const double m = dir > 0 ? v * f : v / f;
    if (m < p.lo) return p.zero_ok ? 0.0 : p.lo;
    return std::min(m, p.hi);
  }
  // Evaluates x (cached); true if it meets the class and beats the best so far.
  bool better(const std::vector<double>& x) {
    if (row_.trial) {
      const Pen pen = pen_at(*row_.strategy, x, row_.model.with_lag_error(row_.errors[0]));
      double predicted = 0;
      try {
        predicted = predicted_cps(w_, row_.head, pen);
      } catch (const InputError&) {
        return false;  // outside the head's limits or the field
      }
      if (predicted <= row_.trial->cps * 1.001) return false;
    }
    return feasible(x);
  }
  bool feasible(const std::vector<double>& x) {
    const auto it = cache_.find(x);
    if (it != cache_.end()) return false;  // seen: it did not improve then and cannot now
    std::optional<Trial> t;
    bool ok = true;
    // One pen for every mark of the row, its frequency included: the speed's, raised (and every
    // mark made again) when a mark's pulses still left a gap, up to the source's maximum.
    double khz = frequency_for(x[0], row_.head);
    for (int round = 0; round <= kFrequencyRounds; ++round) {
      t.reset();
      ok = true;
      double raise = 0;
      for (std::size_t c = 0; ok && c < row_.errors.size() * plants_.size(); ++c) {
        const double e = row_.errors[c / plants_.size()];
        const HeadProfile& model = row_.plant_models.empty() ? row_.model : row_.plant_models[c % plants_.size()];
        std::optional<Trial> one;
        try {
          one = mark_with(w_, row_.head, pen_at(*row_.strategy, x, model.with_lag_error(e)),
                          plants_[c % plants_.size()], khz);
        } catch (const InputError&) {
        } catch (const DeviceError&) {
        }
        ++row_.trials;
        ok = one && meets(one->quality, *row_.level);
        if (!ok) {
          // Worth another round only when the gap is all that failed.
          if (one) {
            Quality without_gap = one->quality;
            without_gap.pulse_gap_max_um = 0;
            if (meets(without_gap, *row_.level)) raise = raised_frequency(khz, one->quality);
          }
          break;
        }
        // The row's figures: the worst of its marks.
        if (!t) {
          t = one;
        } else {
          t->quality = worse_of(t->quality, one->quality);
        }
      }
      if (ok || raise == 0) break;
      khz = raise;
    }
    const Pen pen = pen_at(*row_.strategy, x, row_.model.with_lag_error(row_.errors[0]));
    cache_[x] = ok;
    if (ok && (!row_.trial || t->cps > row_.trial->cps)) {
      row_.trial = t;
      row_.x = x;
      row_.pen = pen;
    }
    return ok;
  }

  const Workload& w_;
  Row& row_;
  bool quick_;
  std::map<std::vector<double>, bool> cache_;
  std::vector<Plant> plants_;
};

std::string mark_args(const Row& r) {
  std::string head = "--head " + r.head_name;
  if (r.head.model.second_order != find_head(r.head_name)->second_order)
    head += " --head-model " + r.head.head_model();
  if (r.head.laser_rise_s > 0) {
    char buf[32];
    std::snprintf(buf, sizeof buf, " --laser-rise-us %g", r.head.laser_rise_s * 1e6);
    head += buf;
  }
  char laser[64];
  std::snprintf(laser, sizeof laser, " --source %s --frequency %g", std::string(to_string(g_source)).c_str(),
                r.trial ? r.trial->frequency_khz : kBaseFrequency_khz);
  std::string material;
  if (g_material_speed_mm_s > 0) {
    char buf[64];
    std::snprintf(buf, sizeof buf, " --dose-reference material --line-speed %.17g", g_material_speed_mm_s);
    material = buf;
  }
  return head + " " + cli::pen_args_string(r.pen) + laser + material;
}

std::string params_text(const Row& r) {
  std::string s;
  char buf[64];
  for (std::size_t i = 1; i < r.x.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%s%s %.3g", s.empty() ? "" : ", ", r.strategy->params[i].name, r.x[i]);
    s += buf;
  }
  return s;
}

std::string model_text(const Row& r) {
  char buf[64];
  if (!r.model_note.empty()) return r.model_note;
  if (r.plants.size() > 1) return "plant set";
  if (r.errors.size() > 1) return "lag 0, ±10 %";
  if (r.errors[0] == 0) return "exact (bound)";
  std::snprintf(buf, sizeof buf, "lag %+.0f %%", r.errors[0] * 100);
  return buf;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"characters per second on the simulated heads (SCANLAB's cps method)"};
  bool quick = false, json = false;
  std::string head_name, strategy_name, text = kCharacters, font = kBuiltinFontName;
  double speed = 0;
  unsigned workers = 2;
  app.add_flag("--short", quick, "coarser parameter search (for CI)");
  app.add_flag("--json", json, "print the rows as JSON (docs/speed.md lists the fields)");
  app.add_option("--head", head_name, "only this head (SL10, SL14, cheap, SA14)");
  app.add_option("--strategy", strategy_name,
                 "only this strategy (blanking, delays, none, none+la, none+ff, none+ff+zv, blanking+ff)");
  app.add_option("--workers", workers, "searches run in parallel (each a producer and a drain thread)");
  app.add_option("--speed", speed, "evaluate this marking speed with default parameters only (mm/s)");
  app.add_option("--text", text, "mark this text instead (diagnosis)");
  app.add_option("--font", font, "in this font instead (diagnosis)");
  std::string source_name = "fiber";
  app.add_option("--source", source_name,
                 "laser source whose frequency range the pulses are searched in: " + laser_source_names());
  app.add_option("--device", g_device,
                 "mark every trial on the simulated scanner (sim) or through the emulated LMC board "
                 "driving it (lmc-emulated[:VARIANT]; virtual time)");
  app.add_option("--max-frequency", g_max_frequency_khz,
                 "the source's top pulse frequency, below its kind's (kHz; a 100 kHz Q-switched fiber: --max-frequency 100)")
      ->check(CLI::Range(1.0, 4000.0));
  app.add_option("--material-speed", g_material_speed_mm_s,
                 "judge dose per mm against a material a single full-power line marks one beam diameter "
                 "wide at this speed, the same for every pen (mm/s; default: each pen's own power / speed)")
      ->check(CLI::Range(1.0, 100000.0));
  CLI11_PARSE(app, argc, argv);

  try {
    const auto t0 = std::chrono::steady_clock::now();
    const std::optional<LaserSource> source = parse_laser_source(source_name);
    if (!source || !limits_of(*source).pulsed)
      throw InputError("--source " + source_name + ": a pulsed source (fiber, mopa, uv) is needed");
    g_source = *source;
    if (g_device != "sim") {
      const auto board = lmc::parse_lmc_spec(g_device);
      if (!board || !board->emulated)
        throw InputError("--device " + g_device + ": cps marks on sim or lmc-emulated[:VARIANT] (a real board has no "
                         "simulated scanner to judge the mark)");
    }
    const std::vector<Strategy> strategies = all_strategies();
    std::vector<const Strategy*> chosen;
    for (const Strategy& s : strategies)
      if (strategy_name.empty() || s.name == strategy_name) chosen.push_back(&s);
    if (chosen.empty()) throw InputError("unknown strategy '" + strategy_name + "'");
    std::vector<std::string> heads = head_names();
    if (!head_name.empty()) {
      const auto h = find_head(head_name);
      if (!h) throw InputError("unknown head '" + head_name + "'");
      heads = {h->name};
    }
    const Workload work(text, font);

    // Identify every simulated head the rows mark on: the planner gets the fitted profile.
    std::map<std::string, HeadProfile> identified;
    auto profile_of = [&](const HeadModel& h) {
      const std::string key = h.name + (h.second_order ? "/2" : "/1");
      if (!identified.count(key)) {
        SimScannerOptions o;
        o.head = h;
        identified[key] = identify_head(o);
      }
      return identified[key];
    };

    // The rows: every head × strategy; model-error, second-order and laser-rise rows on SL10.
    std::vector<Row> rows;
    // Each plant's profile from a picture of its own lag test pattern (the identified limits).
    auto pictured = [&](const RealHead& real, const std::vector<std::string>& plants) {
      std::vector<HeadProfile> models;
      for (const std::string& p : plants) {
        SimScannerOptions o;
        o.head = real.model;
        o.plant = cli::parse_plant_option(p);
        models.push_back(picture_profile(profile_of(real.model), photographed_lag_fit(o)));
      }
      return models;
    };
    auto add = [&](const std::string& name, RealHead real, HeadProfile model, std::vector<double> errors,
                   std::string note, const Strategy* s, std::vector<std::string> plants = {""},
                   std::vector<HeadProfile> plant_models = {}) {
      for (const QualityLimits* level : {&kHighQuality, &kGoodQuality}) {
        Row r;
        r.head_name = name;
        r.head = real;
        r.model = plant_models.empty() ? model : plant_models.front();  // the reported pen's
        r.plant_models = plant_models;
        r.errors = errors;
        r.plants = plants;
        r.model_note = note;
        r.strategy = s;
        r.level = level;
        if (level == &kGoodQuality) r.seed_row = rows.size() - 1;
        rows.push_back(std::move(r));
      }
    };
    for (const std::string& name : heads) {
      const RealHead real{*find_head(name)};
      // A shaper is tuned to SL10's resonance in the set; the other heads' are not known.
      for (const Strategy* s : chosen)
        if (s->shaper_hz == 0 || name == "SL10") add(name, real, profile_of(real.model), {0.0}, "", s);
    }
    const bool sl10 = head_name.empty() || head_name == "SL10";
    if (sl10) {
      const RealHead sl{head_sl10()};
      RealHead second{head_sl10()};
      second.model.second_order = true;
      RealHead rise{head_sl10(), kLaserRise_s};
      for (const Strategy* s : chosen) {
        if (s->shaper_hz > 0) {  // only the rows of the set it is tuned to
          if (!quick) add("SL10", sl, profile_of(sl.model), {0.0}, "", s, kRobustPlants);
          add("SL10", sl, profile_of(sl.model), {0.0}, "picture per plant", s, kRobustPlants,
              pictured(sl, kRobustPlants));
          continue;
        }
        if (s->feed_forward && s->corner == CornerStrategy::none) {
          for (double e : {-0.1, 0.1}) add("SL10", sl, profile_of(sl.model), {e}, "", s);
          add("SL10", sl, profile_of(sl.model), {0.0, -0.1, 0.1}, "", s);
          HeadProfile first = profile_of(second.model);
          first.model = ServoOrder::first;
          add("SL10", second, first, {0.0}, "first-order model", s);
        }
        add("SL10", second, profile_of(second.model), {0.0}, "", s);
        add("SL10", rise, profile_of(rise.model), {0.0}, "", s);
        // The robust rows: not for the strategies that reach nothing useful on the exact head
        // (none, none+la); in the short search only for the blanking and feed-forward baselines.
        if (s->name != "none" && s->name != "none+la" && (!quick || s->name == "blanking" || s->name == "none+ff"))
          add("SL10", sl, profile_of(sl.model), {0.0}, "", s, kRobustPlants);
        // Feed-forward on the same set, each plant planned from its own picture.
        if (s->feed_forward && (!quick || s->name == "none+ff"))
          add("SL10", sl, profile_of(sl.model), {0.0}, "picture per plant", s, kRobustPlants,
              pictured(sl, kRobustPlants));
      }
    }

    if (speed > 0) {  // one speed, default parameters: a diagnosis aid
      for (Row& r : rows) {
        if (r.level != &kHighQuality) continue;
        std::vector<double> x;
        for (const Param& p : r.strategy->params) x.push_back(p.initial);
        x[0] = speed;
        const Trial t =
            mark_with(work, r.head, pen_at(*r.strategy, x, r.model.with_lag_error(r.errors[0])));
        std::printf("%-6s %-6s %-11s %-17s %4.0f µs %6.0f mm/s  max %6.1f µm  rms %5.1f µm  cov %.4f  "
                    "dose %.3f  over %5.1f µm  %.0f kHz gap %.1f µm  dose/mm %.2f  %.4f s  %6.0f cps\n",
                    r.head_name.c_str(), r.head.head_model().c_str(), r.strategy->name.c_str(),
                    model_text(r).c_str(), r.head.laser_rise_s * 1e6, speed,
                    t.quality.max_deviation_um, t.quality.rms_deviation_um, t.quality.coverage,
                    t.quality.dose_ratio_max, t.quality.overshoot_um, t.frequency_khz,
                    t.quality.pulse_gap_max_um, t.quality.dose_per_mm_fraction, t.mark_time_s, t.cps);
      }
      return 0;
    }

    // Every high row is an independent search; each good row starts from its high row's
    // result (which meets "good" too), so a good row is never below its high row.
    std::atomic<std::size_t> next{0};
    std::exception_ptr error;
    std::mutex mutex;
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < rows.size(); ++i)
      if (rows[i].seed_row == SIZE_MAX) order.push_back(i);
    auto worker = [&] {
      for (std::size_t k; (k = next++) < order.size();) {
        try {
          Row& high = rows[order[k]];
          auto started = std::chrono::steady_clock::now();
          auto lap = [&started] {
            const auto now = std::chrono::steady_clock::now();
            const double s = std::chrono::duration<double>(now - started).count();
            started = now;
            return s;
          };
          Search(work, high, quick).run(std::nullopt);
          high.search_s = lap();
          for (Row& good : rows)
            if (good.seed_row == order[k]) {
              if (high.trial) {
                good.trial = high.trial;
                good.x = high.x;
                good.pen = high.pen;
              }
              Search(work, good, quick).run(high.trial ? std::optional(high.x) : std::nullopt);
              good.search_s = lap();
            }
        } catch (...) {
          std::lock_guard<std::mutex> lock(mutex);
          error = std::current_exception();
        }
      }
    };
    std::vector<std::thread> pool;
    for (unsigned i = 0; i < std::max(1u, workers); ++i) pool.emplace_back(worker);
    for (std::thread& t : pool) t.join();
    if (error) std::rethrow_exception(error);
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    const double bound = work.ink_bound_cps();
    if (json) {
      nlohmann::json out = nlohmann::json::array();
      for (const Row& r : rows) {
        nlohmann::json j = {{"head", r.head_name},
                            {"head_model", r.head.head_model()},
                            {"laser_rise_us", r.head.laser_rise_s * 1e6},
                            {"strategy", r.strategy->name},
                            {"quality", to_string(r.level->level)},
                            {"model_error", r.errors.size() > 1 ? 0.1 : r.errors[0]},
                            {"model_error_both_signs", r.errors.size() > 1},
                            {"plants", r.plants},
                            {"exact_plant", r.plants.size() == 1 && r.plants[0].empty()},
                            {"planner_model", r.model_note.empty() ? std::string(to_string(r.model.model)) + "-order"
                                                                   : r.model_note},
                            {"cps", r.trial ? r.trial->cps : 0.0},
                            {"ink_bound_ratio", r.trial ? r.trial->cps / bound : 0.0},
                            {"speed_mm_s", r.trial ? r.x[0] : 0.0},
                            {"source", to_string(g_source)},
                            {"device", g_device},
                            {"trials", r.trials},
                            {"search_s", r.search_s}};
        if (r.trial) {
          nlohmann::json params = nlohmann::json::object();
          for (std::size_t i = 1; i < r.x.size(); ++i) params[r.strategy->params[i].name] = r.x[i];
          j["params"] = params;
          j["mark_time_s"] = r.trial->mark_time_s;
          j["max_deviation_um"] = r.trial->quality.max_deviation_um;
          j["rms_deviation_um"] = r.trial->quality.rms_deviation_um;
          j["coverage_fraction"] = r.trial->quality.coverage;
          j["dose_ratio_max"] = r.trial->quality.dose_ratio_max;
          j["overshoot_um"] = r.trial->quality.overshoot_um;
          j["frequency_khz"] = r.trial->frequency_khz;
          j["pulse_gap_max_um"] = r.trial->quality.pulse_gap_max_um;
          j["dose_per_mm_fraction"] = r.trial->quality.dose_per_mm_fraction;
          j["material_dose_per_mm_fraction"] = r.trial->quality.material_dose_per_mm_fraction;
          j["dose_reference"] = r.trial->quality.dose_vs_material ? "material" : "pen";
          j["mark_args"] = mark_args(r);
        } else {
          j["mark_args"] = nullptr;
        }
        out.push_back(j);
      }
      std::cout << out.dump() << "\n";
      return 0;
    }
    std::printf("cps: 62 characters A–Z a–z 0–9, built-in font, 1 mm cap height, device time; "
                "%s search; %.0f s; marked on %s\n", quick ? "short" : "full", elapsed, g_device.c_str());
    std::printf("ink-only bound: %.1f mm of ink at %.1f m/s = %.0f cps\n", work.ink_mm,
                kInkSpeed_mm_s / 1000, bound);
    const SourceLimits& src = limits_of(g_source);
    std::printf("pulses: %s source (%g .. %g kHz), each pen at the frequency its speed needs; "
                "\"max\" = the source's maximum (a faster pen leaves gaps)\n",
                std::string(src.name).c_str(), src.min_frequency_khz, source_max_khz());
    std::printf("%-5s %-6s %-4s %-11s %-17s %-5s %6s %6s %7s %5s  %s\n", "head", "servo", "rise",
                "strategy", "planner model", "class", "cps", "/ink", "mm/s", "kHz",
                "max µm / rms µm / coverage / dose ratio / dose per mm; parameters");
    for (const Row& r : rows) {
      std::printf("%-5s %-6s %-4.0f %-11s %-17s %-5s ", r.head_name.c_str(),
                  r.head.head_model().c_str(), r.head.laser_rise_s * 1e6, r.strategy->name.c_str(),
                  model_text(r).c_str(), std::string(to_string(r.level->level)).c_str());
      if (!r.trial) {
        std::printf("%6s %6s %7s %5s  not reached\n", "-", "-", "-", "-");
        continue;
      }
      const Quality& q = r.trial->quality;
      char khz[16];
      if (r.trial->frequency_khz >= source_max_khz())
        std::snprintf(khz, sizeof khz, "max");
      else
        std::snprintf(khz, sizeof khz, "%.0f", r.trial->frequency_khz);
      std::printf("%6.0f %6.3f %7.0f %5s  %.1f / %.1f / %.4f / %.2f / %.2f; %s\n", r.trial->cps,
                  r.trial->cps / bound, r.x[0], khz, q.max_deviation_um, q.rms_deviation_um,
                  q.coverage, q.dose_ratio_max, q.dose_per_mm_fraction, params_text(r).c_str());
    }
    std::printf("marker mark options of each row: cps --json (mark_args)\n");
  } catch (const std::exception& e) {
    std::cerr << "cps: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
