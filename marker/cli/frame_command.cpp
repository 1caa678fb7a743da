// `marker frame TEXT [layout options] --device lmc[:SERIAL]|lmc-capture:FILE|lmc-emulated[:VARIANT]
//  [--shape box|hull|strokes] [--speed MM_S] [--laps N] [--no-orientation-mark] [LMC options]`
// Red-light framing, how an operator aligns a part: the red pointer traces a small "F" at the
// job's +x side (the orientation mark: on the part it must read as an F, or the head's axes are
// not what --swap-xy / --flip-x / --flip-y say) and the job's bounding box (or its hull, or the
// strokes) with the laser port off and the master oscillator closed, lap after lap until Ctrl-C
// / SIGTERM (or --laps), then the red pointer goes off. Stopping it with Ctrl-C is the normal
// end: exit status 0.
#include <atomic>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <thread>

#include "base/error.hpp"
#include "driver/lmc/lmc_open.hpp"
#include "marker/cli/commands.hpp"
#include "marker/cli/interrupt.hpp"
#include "marker/cli/layout_options.hpp"
#include "marker/cli/lmc_options.hpp"
#include "marker/cli/option_ranges.hpp"
#include "marker/frame/frame_paths.hpp"
#include "marker/frame/orientation_mark.hpp"
#include "marker/limits/device_settings.hpp"

namespace mark::cli {

Command make_frame_command() {
  struct Args {
    std::string text;
    LayoutArgs layout;
    LmcArgs lmc;
    std::string device;
    std::string shape;
    double speed_mm_s = 0;
    long long laps = 0;
    bool json = false;
    bool no_orientation_mark = false;
  };
  auto a = std::make_shared<Args>();
  return Command(
      [a](CLI::App& app) {
        auto* sub = app.add_subcommand(
            "frame", "trace the job's outline with the red pointer (laser off) until Ctrl-C");
        sub->add_option("text", a->text, "text of the job (UTF-8; \\n starts a new line)")->required();
        add_layout_options(*sub, a->layout);
        add_setting(*sub, kDevice, a->device);
        a->device = "lmc";  // framing needs a board
        add_setting(*sub, kFrameShape, a->shape);
        add_setting(*sub, kFrameSpeed, a->speed_mm_s);
        add_setting(*sub, kFrameLaps, a->laps);
        sub->add_flag("--json", a->json,
                      "print {laps, packets, stopped, shape, orientation_mark, width_mm, height_mm, speed_mm_s} at the end");
        add_setting(*sub, kNoOrientationMark, a->no_orientation_mark);
        add_lmc_options(*sub, a->lmc);
        return sub;
      },
      [a] {
        const auto spec = lmc::parse_lmc_spec(a->device);
        if (!spec)
          throw InputError("--device '" + a->device +
                           "': framing needs an LMC board (lmc, lmc:SERIAL, lmc-capture:FILE or lmc-emulated[:VARIANT])");
        if (spec->capture && a->laps == 0)
          throw InputError("--device lmc-capture: give --laps (an endless frame would never finish the capture)");
        const LaidOutText laid = build_figure(a->text, a->layout);
        auto paths = frame_paths(laid.figure, parse_frame_shape(a->shape));
        // The F first: the operator checks the orientation before looking at the outline.
        if (!a->no_orientation_mark)
          paths.insert(paths.begin(), orientation_mark(laid.figure.bounds(), a->layout.field_mm));
        const auto device = lmc::open_lmc(*spec, to_lmc_options(a->lmc, a->layout.field_mm));
        const Box b = laid.figure.bounds();
        if (!a->json)
          std::fprintf(stderr, "framing %s %.2f × %.2f mm on %s with the red pointer%s%s\n",
                       a->shape.c_str(), b.width(), b.height(), device->describe().name.c_str(),
                       a->no_orientation_mark ? "" : "; the F at its right must read as an F on the part",
                       a->laps ? "" : "; Ctrl-C to stop");

        // Ctrl-C / SIGTERM: the handler only raises the flag; this watcher turns it into
        // abort(), which stops the board and switches the red pointer off.
        std::atomic<bool> done{false};
        std::thread watcher([&] {
          while (!done.load()) {
            if (interrupt_flag().requested()) {
              device->abort();
              return;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
          }
        });
        lmc::FrameReport r;
        try {
          r = device->frame(paths, lmc::FrameOptions{a->speed_mm_s, static_cast<std::uint64_t>(a->laps)});
        } catch (...) {
          done = true;
          watcher.join();
          throw;
        }
        done = true;
        watcher.join();
        if (a->json) {
          std::cout << nlohmann::json{{"laps", r.laps},           {"packets", r.packets},
                                      {"stopped", r.stopped},     {"shape", a->shape},
                                      {"orientation_mark", !a->no_orientation_mark},
                                      {"width_mm", b.width()}, {"height_mm", b.height()},
                                      {"speed_mm_s", a->speed_mm_s}}
                           .dump()
                    << "\n";
        } else {
          std::printf("framed %llu laps (%llu packets)%s; red pointer off\n",
                      static_cast<unsigned long long>(r.laps), static_cast<unsigned long long>(r.packets),
                      r.stopped ? ", stopped" : "");
        }
        return 0;
      });
}

}  // namespace mark::cli
