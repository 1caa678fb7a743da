// `marker gravure IMAGE [--mask LW.png] [--screen L[xC]] [--cell-rate HZ] [--resolution PX_MM]
//  [--stagger] [--ct-depth UM ...] [--lw-depth UM ...] [--lift UM] [--stylus-angle DEG]
//  [--head F:D:G,...] [--nominal-head F:D:G,...] [--tune auto|nominal|off] [--notch F:D:DB]...
//  [--emphasis F:D:FT:DT] [--target HZ] [--real-time] [--no-compare] [--json] [--preview FILE]`
// Engraves the image on the simulated stylus head (US 6,007,230): toolpath from the image data,
// notch / emphasis filtering, optional automatic tuning, and the engraving compared with what
// was intended, with and without the filters.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>

#include "base/error.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/gravure_options.hpp"
#include "marker/cli/interrupt.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/cli/output_options.hpp"
#include "marker/output/output_file.hpp"
#include "marker/cli/print.hpp"
#include "marker/gravure/gravure_job.hpp"
#include "marker/gravure/gravure_json.hpp"
#include "marker/gravure/gravure_preview.hpp"
#include "marker/gravure/head_design.hpp"
#include "marker/limits/gravure_settings.hpp"

namespace mark::cli {
namespace {

struct GravureArgs {
  std::string image;
  std::string mask;
  std::string screen;
  int cell_rate_hz = 0;
  double resolution = 0;
  bool stagger = false;
  GravureSetup setup;
  double stylus_angle_deg = 0;
  std::string head;
  std::string nominal_head;
  double sense_noise_um = 0;
  double sense_velocity_noise_um_s = 0;
  std::string tune;
  std::string tune_from;
  std::vector<std::string> notches;
  std::string emphasis;
  double target_hz = 0;
  bool real_time = false;
  bool no_compare = false;
  bool json = false;
  std::string preview;
};

GravureJobSpec make_spec(const GravureArgs& a) {
  GravureJobSpec spec;
  parse_screen(flag(kScreen), a.screen, spec.screen);
  spec.screen.cell_rate_hz = static_cast<std::uint32_t>(a.cell_rate_hz);
  spec.screen.stagger = a.stagger;
  spec.px_per_mm = a.resolution;
  spec.setup = a.setup;
  spec.stylus_angle_deg = a.stylus_angle_deg;
  if (!a.head.empty()) spec.head.head = parse_head(flag(kStylusHead), a.head);
  if (!a.nominal_head.empty()) spec.nominal_head = parse_head(flag(kNominalHead), a.nominal_head);
  spec.head.sense_noise_um = a.sense_noise_um;
  spec.head.sense_velocity_noise_um_s = a.sense_velocity_noise_um_s;
  if (a.tune_from == "both") spec.tuning.source = ResponseSource::fused;
  else if (a.tune_from == "position") spec.tuning.source = ResponseSource::position;
  else if (a.tune_from == "velocity") spec.tuning.source = ResponseSource::velocity;
  else throw InputError(flag(kTuneFrom) + " '" + a.tune_from + "': expected " + std::string(kTuneFrom.choices));
  spec.tuning.target.corner_hz = a.target_hz;

  const bool manual = !a.notches.empty() || !a.emphasis.empty();
  if (a.tune == "auto") spec.filters = FilterChoice::tuned;
  else if (a.tune == "nominal") spec.filters = FilterChoice::nominal;
  else if (a.tune == "off") spec.filters = FilterChoice::off;
  else throw InputError(flag(kTune) + " '" + a.tune + "': expected " + std::string(kTune.choices));
  if (manual) {
    if (a.tune != "nominal") throw InputError("--notch / --emphasis set the filters by hand: they cannot be combined with --tune " + a.tune);
    spec.filters = FilterChoice::manual;
    for (const std::string& n : a.notches) spec.manual_bank.sections.push_back(parse_notch(flag(kNotch), n));
    if (!a.emphasis.empty()) spec.manual_bank.sections.push_back(parse_emphasis(flag(kEmphasis), a.emphasis));
    spec.manual_bank.gain = 1 / spec.nominal_head.static_gain();
  }
  spec.compare_unfiltered = !a.no_compare;
  spec.run.virtual_time = !a.real_time;
  spec.run.stop = &interrupt_flag();
  spec.image = read_gray_image(a.image);
  if (!a.mask.empty()) spec.mask = read_gray_image(a.mask);
  return spec;
}

void print_summary(const GravureReport& r) {
  print("engraved %llu cells (%u tracks of %u) in %.3f s device time, %llu samples at %.0f kHz\n",
        static_cast<unsigned long long>(r.cells), r.layout.tracks, r.layout.cells_per_track,
        r.filtered.run.report.device_time_s, static_cast<unsigned long long>(r.samples), kStylusRate_hz / 1000);
  print("cells: %llu white, %llu single, %llu channel (> 90 %%), %llu split (double frequency), %llu line-work\n",
        static_cast<unsigned long long>(r.counts.white), static_cast<unsigned long long>(r.counts.single),
        static_cast<unsigned long long>(r.counts.channel), static_cast<unsigned long long>(r.counts.split),
        static_cast<unsigned long long>(r.counts.line_work));
  print("filters %s (%zu sections): depth error rms %.3f µm, max %.3f µm; drive peak %.1f µm\n",
        std::string(to_string(r.filters)).c_str(), r.bank.sections.size(), r.filtered.depth_error.rms_um,
        r.filtered.depth_error.max_um, r.filtered.drive_peak_um);
  print("against the cells the image asked for: depth error rms %.3f µm, max %.3f µm; deepest cut %.1f µm "
        "(full cell %.1f µm)\n",
        r.filtered.depth_error_vs_cells.rms_um, r.filtered.depth_error_vs_cells.max_um, r.filtered.max_cut_um,
        r.full_cell_depth_um);
  if (r.unfiltered)
    print("without filters:   depth error rms %.3f µm, max %.3f µm (%.1f× the filtered rms)\n",
          r.unfiltered->depth_error.rms_um, r.unfiltered->depth_error.max_um,
          r.unfiltered->depth_error.rms_um / std::max(1e-12, r.filtered.depth_error.rms_um));
  if (r.tuning) {
    print("auto-tuned head: %s (fit error %.2f %%); tuned response %+.2f .. %+.2f dB to 10 kHz%s\n",
          describe(r.tuning->fit.model).c_str(), 100 * r.tuning->fit.rms_relative_error, r.tuning->flatness.min_db,
          r.tuning->flatness.max_db, r.tuning->within_tolerance ? "" : " — OUTSIDE ±1 dB");
  }
}

int run_gravure(const GravureArgs& a) {
  // The preview's path before the engraving, not after it (an engraving runs for seconds).
  check_standard_output({{"--preview", &a.preview}}, a.json);
  if (!a.preview.empty()) check_output_path("--preview", a.preview, {".svg", ".png"});
  const GravureJobSpec spec = make_spec(a);
  GravureReport report = run_gravure_job(spec);
  // Ctrl-C: the drain lifted the stylus within one block; nothing is written, exit 130.
  if (report.cancelled) throw Interrupted();
  if (!a.preview.empty()) write_gravure_preview(report.layout, report.intended_um, report.engraved_um, a.preview);
  if (a.json)
    std::cout << to_json(spec, report).dump(2) << "\n";
  else
    print_summary(report);
  if (!a.preview.empty()) std::cerr << "marker: wrote " << a.preview << "\n";
  return 0;
}

void add_setup_options(CLI::App& sub, CellSetup& s, const Quantity& depth, const Quantity& channel,
                       const Quantity& gain, const Quantity& offset, const std::string& group) {
  for (const auto& [setting, value] : {std::pair{&depth, &s.full_cell_depth_um}, {&channel, &s.channel_depth_um},
                                       {&gain, &s.gain}, {&offset, &s.offset_um}})
    add_setting(sub, *setting, *value)->group(group);
}

}  // namespace

Command make_gravure_command() {
  auto a = std::make_shared<GravureArgs>();
  return Command(
      [a](CLI::App& app) {
        auto* sub = app.add_subcommand("gravure", "engrave an image on the simulated gravure stylus head");
        sub->add_option("image", a->image, "8-bit grey image, PNG or PGM (white 0 % … black 100 % density)")->required();
        sub->add_option("--mask", a->mask, "line-work mask of the same size: dark pixels are line-work (LW)");
        add_setting(*sub, kScreen, a->screen);
        add_setting(*sub, kCellRate, a->cell_rate_hz);
        add_setting(*sub, kResolution, a->resolution);
        add_setting(*sub, kStagger, a->stagger);
        add_setup_options(*sub, a->setup.ct, kCtDepth, kCtChannel, kCtGain, kCtOffset, "CT setup");
        add_setup_options(*sub, a->setup.lw, kLwDepth, kLwChannel, kLwGain, kLwOffset, "LW setup");
        add_setting(*sub, kLift, a->setup.lift_um);
        add_setting(*sub, kStylusAngle, a->stylus_angle_deg);
        const std::string head = "Head and filters";
        add_setting(*sub, kStylusHead, a->head)->group(head);
        add_setting(*sub, kNominalHead, a->nominal_head)->group(head);
        add_setting(*sub, kSenseNoise, a->sense_noise_um)->group(head);
        add_setting(*sub, kSenseVelocityNoise, a->sense_velocity_noise_um_s)->group(head);
        add_setting(*sub, kTune, a->tune)->group(head);
        add_setting(*sub, kTuneFrom, a->tune_from)->group(head);
        add_setting(*sub, kNotch, a->notches)->group(head);
        add_setting(*sub, kEmphasis, a->emphasis)->group(head);
        add_setting(*sub, kTargetCorner, a->target_hz)->group(head);
        add_setting(*sub, kRealTime, a->real_time);
        add_setting(*sub, kNoCompare, a->no_compare);
        sub->add_flag("--json", a->json, "print one JSON object with the job's figures");
        sub->add_option("--preview", a->preview, "write intended and engraved cells side by side (.png or .svg)");
        return sub;
      },
      [a] { return run_gravure(*a); });
}

}  // namespace mark::cli
