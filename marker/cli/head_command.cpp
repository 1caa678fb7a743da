// `marker head identify [--head NAME] [--head-model first|second] [--head-zeta Z] [-o FILE]
//  [--json]`: runs the head response test (steps, ramps, a chirp, large steps) on the simulated
// head, fits its servo model and limits from the recorded positions alone, and saves them as a
// head profile (docs/speed.md) that the planner feeds forward.
#include <cstdio>
#include <iostream>

#include "marker/cli/commands.hpp"
#include "marker/cli/head_options.hpp"
#include "marker/cli/output_options.hpp"
#include "marker/head/head_fit.hpp"
#include "marker/output/output_file.hpp"

namespace mark::cli {

Command make_head_command() {
  struct Args {
    HeadArgs head;
    std::string output;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  return Command(
      [a](CLI::App& app) {
        auto* head = app.add_subcommand("head", "scan-head tools");
        head->require_subcommand(1);
        auto* sub = head->add_subcommand(
            "identify", "measure the simulated head's response and save its head profile");
        add_head_options(*sub, a->head, false);
        sub->add_option("-o,--output", a->output,
                        "head profile file to write (default: head-<NAME>.json)");
        sub->add_flag("--json", a->json, "print the profile as JSON instead of a summary");
        return sub;
      },
      [a] {
        SimScannerOptions sim;
        sim.head = simulated_head(a->head);
        const std::string path = a->output.empty() ? "head-" + sim.head.name + ".json" : a->output;
        check_standard_output({{"--output", &path}}, a->json);
        check_output_path("--output", path);
        const HeadProfile p = identify_head(sim);
        save_head_profile(p, path);
        if (a->json) {
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
      });
}

}  // namespace mark::cli
