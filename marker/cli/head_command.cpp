// `marker head identify [--head NAME] [--head-model first|second] [--head-zeta Z] [-o FILE]
//  [--json]`: runs the head response test (steps, ramps, a chirp, large steps) on the simulated
// head, fits its servo model and limits from the recorded positions alone, and saves them as a
// head profile (docs/speed.md) that the planner feeds forward.
//
// For a head that reports no position, from a picture of a mark instead (docs/speed.md,
// "Identification from a picture"):
//   `marker head test-pattern [--head …] [--plant …] [--device DEV] [-o pattern.json]
//   [--picture scan.png]` marks the lag test pattern (marker/head/lag_pattern.hpp) on the
//   simulated head (or on an LMC board, real or emulated: marker/head/lag_program.hpp) and
//   writes the pattern file, and its scan where the device is simulated;
//   `marker head identify --from-image scan.png --pixel-um P --pattern pattern.json` fits the
//   ramp lag from the picture and saves it as a first-order profile, the limits the --head
//   preset's (a picture does not show them).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "driver/laser_source.hpp"
#include "driver/lmc/lmc_spec.hpp"
#include "driver/sim/grey_png.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/console_progress.hpp"
#include "marker/cli/device_factory.hpp"
#include "marker/cli/head_options.hpp"
#include "marker/cli/interrupt.hpp"
#include "marker/cli/lmc_options.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/output_options.hpp"
#include "marker/cli/pen_options.hpp"
#include "marker/cli/plant_option.hpp"
#include "marker/head/head_fit.hpp"
#include "marker/head/lag_fit.hpp"
#include "marker/head/lag_photo.hpp"
#include "marker/head/lag_program.hpp"
#include "marker/job/board_watcher.hpp"
#include "marker/limits/head_settings.hpp"
#include "marker/limits/marking_settings.hpp"
#include "marker/limits/pen_settings.hpp"
#include "marker/output/output_file.hpp"

namespace mark::cli {
namespace {

struct IdentifyArgs {
  HeadArgs head;
  std::string output;
  bool json = false;
  std::string from_image, pattern;
  std::optional<double> pixel_um;
};

int identify_from_response(const IdentifyArgs& a) {
  SimScannerOptions sim;
  sim.head = simulated_head(a.head);
  const std::string path = a.output.empty() ? "head-" + sim.head.name + ".json" : a.output;
  check_standard_output({{"--output", &path}}, a.json);
  check_output_path("--output", path);
  const HeadProfile p = identify_head(sim);
  save_head_profile(p, path);
  if (a.json) {
    std::cout << head_profile_json(p);
    return 0;
  }
  std::printf("head %s: identified from its response to steps, ramps, a chirp and large steps\n",
              p.head.c_str());
  std::printf("first order:  tau %.4f ms (fit rms %.4f µm)\n", p.tau_s * 1e3, p.fit_rms_first_um);
  std::printf("second order: omega_n %.0f rad/s, zeta %.3f, ramp lag %.4f ms (fit rms %.4f µm)\n",
              p.omega_n_rad_s, p.zeta, 2 * p.zeta / p.omega_n_rad_s * 1e3, p.fit_rms_second_um);
  std::printf("model: %s order; limits: speed %.0f mm/s, acceleration %.3g mm/s²\n",
              std::string(to_string(p.model)).c_str(), p.max_speed_mm_s, p.max_accel_mm_s2);
  std::printf("wrote %s\n", path.c_str());
  return 0;
}

int identify_from_image(const IdentifyArgs& a) {
  if (a.pattern.empty()) throw InputError("--from-image needs --pattern FILE (the pattern file test-pattern wrote)");
  if (!a.pixel_um) throw InputError("--from-image needs --pixel-um (the picture's pixel on the part, µm)");
  if (!a.head.model.empty() || a.head.zeta)
    throw InputError("--head-model and --head-zeta do not apply with --from-image: the picture's lines give "
                     "the ramp lag and its corners the servo's order and ζ");
  const HeadModel head = simulated_head(a.head);
  const std::string path = a.output.empty() ? "head-" + head.name + ".json" : a.output;
  check_standard_output({{"--output", &path}}, a.json);
  check_output_path("--output", path);
  // Ctrl-C before the profile is written stops the command with nothing written (the watchdog).
  ConsoleProgress progress = command_progress(a.json);
  const LagPattern pattern = load_lag_pattern(a.pattern);
  progress.step("reading the picture", 0, 2);
  const GrayImage picture = read_gray_image(a.from_image);
  progress.step("fitting the lag", 1, 2);
  const LagFit fit = fit_lag_from_image(picture, *a.pixel_um / 1000, pattern, a.from_image);

  const HeadProfile p = picture_profile(datasheet_profile(head), fit);
  const CornerFit& corners = fit.corners;
  progress.writing_files();
  save_head_profile(p, path);
  if (a.json) {
    nlohmann::ordered_json j;
    j["picture"] = a.from_image;
    j["pattern"] = a.pattern;
    j["pixel_um"] = *a.pixel_um;
    j["tau_s"] = fit.tau_s;
    j["tau_x_s"] = fit.tau_x_s;
    j["tau_y_s"] = fit.tau_y_s;
    j["fit_rms_um"] = fit.rms_um;
    for (const LagPairFigure& f : fit.pairs)
      j["pairs"].push_back({{"axis", f.axis == 0 ? "x" : "y"},
                            {"speed_mm_s", f.speed_mm_s},
                            {"ends_apart_mm", f.ends_apart_mm},
                            {"residual_um", f.residual_um}});
    if (!corners.corners.empty()) {
      j["model"] = to_string(p.model);
      j["zeta"] = corners.zeta;
      j["omega_n_rad_s"] = corners.omega_n_rad_s;
      j["corner_rms_first_um"] = corners.rms_first_um;
      j["corner_rms_second_um"] = corners.rms_second_um;
      for (const CornerFigure& c : corners.corners)
        j["corners"].push_back({{"axis", c.axis == 0 ? "x" : "y"},
                                {"speed_mm_s", c.speed_mm_s},
                                {"places", c.rows},
                                {"overshoot_um", c.overshoot_um},
                                {"rms_first_um", c.rms_first_um},
                                {"rms_second_um", c.rms_second_um}});
      const RingFit& ring = corners.ring;
      j["resonance"] = {{"seen", ring.seen},
                        {"frequency_hz", ring.frequency_hz},
                        {"zeta", ring.zeta},
                        {"amplitude_um", ring.amplitude_um},
                        {"rms_before_um", ring.rms_before_um},
                        {"rms_after_um", ring.rms_after_um}};
    }
    j["profile"] = path;
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::printf("head %s: ramp lag fitted from %s (%g µm pixels), %zu line pairs\n", p.head.c_str(),
              a.from_image.c_str(), *a.pixel_um, fit.pairs.size());
  std::printf("tau %.4f ms (x %.4f ms, y %.4f ms), fit rms %.2f µm\n", fit.tau_s * 1e3, fit.tau_x_s * 1e3,
              fit.tau_y_s * 1e3, fit.rms_um);
  if (corners.corners.empty()) {
    std::printf("no corners in the pattern (a pattern file from before they were added): first order assumed\n");
  } else {
    double most = 0;
    for (const CornerFigure& c : corners.corners) most = std::max(most, c.overshoot_um);
    std::printf("%zu corners: overshoot up to %.1f µm; first order rms %.2f µm, second order (zeta %.3f, omega_n %.0f "
                "rad/s) rms %.2f µm\n",
                corners.corners.size(), most, corners.rms_first_um, corners.zeta, corners.omega_n_rad_s,
                corners.rms_second_um);
    const RingFit& ring = corners.ring;
    if (ring.seen)
      std::printf("mirror resonance: %.0f Hz, zeta %.3f, ringing %.1f µm after the corners (what the model leaves: rms "
                  "%.2f → %.2f µm); --lookahead and --feed-forward shape against it\n",
                  ring.frequency_hz, ring.zeta, ring.amplitude_um, ring.rms_before_um, ring.rms_after_um);
    else
      std::printf("no mirror resonance seen after the corners (best fit %.0f Hz: rms %.2f → %.2f µm)\n",
                  ring.frequency_hz, ring.rms_before_um, ring.rms_after_um);
  }
  std::printf("model: %s order; limits (the preset's, not measured): speed %.0f mm/s, acceleration %.3g mm/s²\n",
              std::string(to_string(p.model)).c_str(), p.max_speed_mm_s, p.max_accel_mm_s2);
  std::printf("wrote %s\n", path.c_str());
  return 0;
}

struct PatternArgs {
  HeadArgs head;
  std::string output = "lag-pattern.json";
  std::string picture = "lag-pattern.png";
  bool json = false;
  std::string device{kDevice.value};
  LmcArgs lmc;
  LaserSettings laser;
  std::string source{kLaserSource.value};
  bool virtual_time = false;
  std::vector<const CLI::Option*> board_options;  // refused with --device sim
  const CLI::Option* picture_option = nullptr;     // refused with a real board
  const CLI::Option* frequency_option = nullptr;   // not given: the pulses' frequency is picked
};

struct MarkedPattern {
  std::string device;                 // the device's name
  std::optional<GreyImage> picture;   // none from a real board: the user scans the part
};

// On a command-level board (the LMC, the emulated one): the pattern as a bare program, Ctrl-C
// aborting the board (laser off) within the watcher's poll, and a picture from the simulated
// scanner behind an emulated board.
MarkedPattern mark_on_board(const PatternArgs& a, const SimScannerOptions& sim, const LagPattern& pattern) {
  JobSpec job;
  job.head = sim.head;
  job.laser = a.laser;
  job.laser.source = *parse_laser_source(a.source);
  // identify follows each line's ink across the picture: pulses farther apart than the spot
  // leave a row of dots on the fast lines, which it cannot follow (and a camera sees them).
  // Unless --frequency says otherwise, the pulses are half a spot apart on the fastest line,
  // within the source's range.
  const SourceLimits source = limits_of(job.laser.source);
  const double overlapping_khz = std::ceil(2 * pattern.fastest_mm_s() / sim.head.spot_diameter_um);
  if (source.pulsed && a.frequency_option->count() == 0) {
    job.laser.frequency_khz = std::clamp(overlapping_khz, source.min_frequency_khz, source.max_frequency_khz);
    if (!a.json)
      std::fprintf(stderr,
                   "marker: pulses at %g kHz, %.0f µm apart on the fastest line (%g mm/s, %g µm spot); "
                   "--frequency sets another\n",
                   job.laser.frequency_khz, pattern.fastest_mm_s() / job.laser.frequency_khz,
                   pattern.fastest_mm_s(), sim.head.spot_diameter_um);
  }
  check_laser_settings(job.laser, "--source " + a.source + ": ");
  SimSettings settings;
  settings.laser_rise_s = sim.laser_rise_s;
  settings.plant = sim.plant;
  settings.virtual_time = a.virtual_time;
  // Refused before the device opens (a capture file would be begun): only a simulated head
  // (behind the emulated board) has a plant and gives a picture.
  const auto spec = lmc::parse_lmc_spec(a.device);
  if (spec && !spec->emulated) {
    if (!settings.plant.is_model())
      throw InputError("--plant '" + a.head.plant + "': a real board drives its own head; the plant is the simulated one's");
    if (a.picture_option->count() > 0)
      throw InputError("--picture: a real board's mark is on the part; scan or photograph it and give that picture to "
                       "`marker head identify --from-image`");
  }
  const OpenedDevice opened = open_device(a.device, job, settings, a.lmc);
  CommandDevice* board = opened.device->as_command_device();
  if (!board) throw InputError("--device '" + a.device + "': the lag pattern on a device goes to a board (lmc…)");
  const DeviceDescription desc = opened.device->describe();
  const LagProgram program = lag_pattern_program(pattern, job.laser, desc);
  const double pitch_um = pattern.fastest_mm_s() / job.laser.frequency_khz;  // mm/s over kHz
  if (source.pulsed && pitch_um > sim.head.spot_diameter_um)
    std::fprintf(stderr,
                 "marker: warning: at %g kHz the pattern's fastest line (%g mm/s) puts pulses %.0f µm apart on a "
                 "%g µm spot: its lines are rows of dots that identify cannot follow; --frequency %.0f or more "
                 "puts them half a spot apart\n",
                 job.laser.frequency_khz, pattern.fastest_mm_s(), pitch_um, sim.head.spot_diameter_um,
                 overlapping_khz);
  if (!a.json)
    std::fprintf(stderr, "marking the lag pattern on %s (%zu commands); Ctrl-C stops it with the laser off\n",
                 desc.name.c_str(), program.commands.size());
  const DeviceReport report = run_board_program(*board, program.header, program.commands, &interrupt_flag());
  if (report.outcome == DeviceState::aborted)
    throw Interrupted("marking the lag pattern on " + desc.name + " (" + std::to_string(report.commands_done) +
                      " of " + std::to_string(program.commands.size()) + " commands sent, laser off)");
  if (report.outcome != DeviceState::done)
    throw InputError("the lag pattern on " + desc.name + " failed: " +
                     (report.fault ? report.fault->message : std::string("the board ended the job")) +
                     "; nothing was written");
  MarkedPattern marked{desc.name, std::nullopt};
  if (opened.simulator) marked.picture = photograph_lag_dose(opened.simulator->scanner().picture_dose(), pattern);
  return marked;
}

int test_pattern(const PatternArgs& a) {
  check_standard_output({{"--output", &a.output}, {"--picture", &a.picture}}, a.json);
  check_output_path("--output", a.output, {".json"});
  check_output_path("--picture", a.picture, {".png"});
  SimScannerOptions sim;
  sim.head = simulated_head(a.head);
  sim.laser_rise_s = a.head.laser_rise_us * 1e-6;
  sim.plant = parse_plant_option(a.head.plant);
  const LagPattern pattern = lag_pattern(sim.head);
  MarkedPattern marked;
  if (a.device == "sim") {
    for (const CLI::Option* o : a.board_options)
      if (o->count() > 0)
        throw InputError(o->get_name() + " applies to a board (--device lmc…); the simulator marks the pattern "
                                         "at full power on its fastest line");
    // Ctrl-C before the files are written stops the command with nothing written (the watchdog).
    ConsoleProgress progress = command_progress(a.json);
    progress.step("marking and photographing the lag pattern", 0, 1);
    marked = {"the simulator", photograph_lag_pattern(sim, pattern)};
    progress.writing_files();
  } else {
    marked = mark_on_board(a, sim, pattern);
  }
  write_file_whole(a.output, lag_pattern_json(pattern));
  if (marked.picture) write_file_whole(a.picture, encode_grey_png(*marked.picture));
  const Vec2 lo = pattern.min(), hi = pattern.max();
  if (a.json) {
    nlohmann::ordered_json j;
    j["head"] = sim.head.name;
    j["device"] = marked.device;
    j["pattern"] = a.output;
    j["lines"] = pattern.lines.size();
    j["speeds_mm_s"] = pattern.speeds_mm_s;
    j["corners"] = pattern.corners.size();
    j["corner_speeds_mm_s"] = pattern.corner_speeds_mm_s;
    if (marked.picture) {
      j["picture"] = a.picture;
      j["pixel_um"] = marked.picture->pixel_mm * 1e3;
      j["width_px"] = marked.picture->width;
      j["height_px"] = marked.picture->height;
    }
    std::cout << j.dump(2) << "\n";
    return 0;
  }
  std::printf("head %s: lag pattern of %zu lines and %zu corners (%g × %g mm), every delay zero, marked on %s\n",
              sim.head.name.c_str(), pattern.lines.size(), pattern.corners.size(), hi.x - lo.x, hi.y - lo.y,
              marked.device.c_str());
  if (!marked.picture) {
    std::printf("wrote %s; scan or photograph the part square-on at %g µm per pixel or finer, then\n",
                a.output.c_str(), kLagPhotoPixelUm);
    std::printf("  marker head identify --from-image SCAN.png --pixel-um P --pattern %s --head %s\n",
                a.output.c_str(), sim.head.name.c_str());
    return 0;
  }
  const GreyImage& picture = *marked.picture;
  std::printf("wrote %s and %s (%d × %d px of %g µm); fit it with\n", a.output.c_str(), a.picture.c_str(),
              picture.width, picture.height, picture.pixel_mm * 1e3);
  std::printf("  marker head identify --from-image %s --pixel-um %g --pattern %s --head %s\n", a.picture.c_str(),
              picture.pixel_mm * 1e3, a.output.c_str(), sim.head.name.c_str());
  return 0;
}

}  // namespace

Command make_head_command() {
  auto a = std::make_shared<IdentifyArgs>();
  auto t = std::make_shared<PatternArgs>();
  auto pattern_app = std::make_shared<CLI::App*>(nullptr);
  return Command(
      [a, t, pattern_app](CLI::App& app) {
        auto* head = app.add_subcommand("head", "scan-head tools");
        head->require_subcommand(1);
        auto* sub = head->add_subcommand(
            "identify", "measure the simulated head's response (or fit a picture of the lag pattern) and save its head profile");
        add_head_options(*sub, a->head, false);
        sub->add_option("-o,--output", a->output,
                        "head profile file to write (default: head-<NAME>.json)");
        sub->add_flag("--json", a->json, "print the profile (or the picture's fit) as JSON instead of a summary");
        sub->add_option("--from-image", a->from_image,
                        "a picture (PNG or PGM) of the lag pattern as marked: fit the lag from it")
            ->check(CLI::ExistingFile);
        sub->add_option("--pattern", a->pattern, "the pattern file `head test-pattern` wrote")
            ->check(CLI::ExistingFile);
        add_setting(*sub, kPicturePixel, a->pixel_um);
        auto* pat = head->add_subcommand(
            "test-pattern", "mark the lag test pattern (on the simulated head, the emulated or a real LMC board) and write its pattern file, and its scan where the device is simulated");
        add_head_options(*pat, t->head, true);
        pat->add_option("-o,--output", t->output, "pattern file to write (.json; default lag-pattern.json)");
        t->picture_option = pat->add_option(
            "--picture", t->picture,
            "the scan of the marked pattern to write, where the device is simulated (.png; default lag-pattern.png)");
        pat->add_flag("--json", t->json, "print a summary as JSON");
        add_setting(*pat, kDevice, t->device);
        add_setting(*pat, kVirtualTime, t->virtual_time);
        // The board's options: the simulator marks at full power on the fastest line, no board
        // between, so there they would be ignored; they are refused instead.
        const std::size_t before = pat->get_options().size();
        add_lmc_options(*pat, t->lmc);
        add_laser_options(*pat, t->laser);
        t->frequency_option = pat->get_option("--frequency");
        add_setting(*pat, kLaserSource, t->source);
        const auto options = pat->get_options();
        t->board_options.assign(options.begin() + static_cast<std::ptrdiff_t>(before), options.end());
        *pattern_app = pat;
        return head;
      },
      [a, t, pattern_app] {
        if ((*pattern_app)->parsed()) return test_pattern(*t);
        if (!a->from_image.empty()) return identify_from_image(*a);
        if (!a->pattern.empty() || a->pixel_um)
          throw InputError("--pattern and --pixel-um go with --from-image");
        return identify_from_response(*a);
      });
}

}  // namespace mark::cli
