// `marker devices [--json] [--no-serial]`: the LMC boards on USB (0x9588:0x9899) with bus,
// address, port and board serial — the serial is what `--device lmc:SERIAL` selects — and the
// laser sources the driver sends words for. A board does not report which source is wired to it:
// that is the pen's `source` (--source, a job file pen's "source"). A board that cannot be
// opened (another program has it, no permission) is listed with the reason.
#include <iostream>
#include <nlohmann/json.hpp>

#include "driver/laser_source.hpp"
#include "driver/lmc/usb_discovery.hpp"
#include "marker/cli/commands.hpp"

namespace mark::cli {

Command make_devices_command() {
  struct Args {
    bool json = false;
    bool no_serial = false;
  };
  auto a = std::make_shared<Args>();
  return Command(
      [a](CLI::App& app) {
        auto* sub = app.add_subcommand("devices", "list the LMC galvo boards on USB (bus, address, serial)");
        sub->add_flag("--json", a->json, "print {\"boards\": [...]} (see docs/lmc.md)");
        sub->add_flag("--no-serial", a->no_serial, "do not open the boards to read their serials");
        return sub;
      },
      [a] {
        const auto boards = lmc::list_usb_boards(!a->no_serial);
        nlohmann::json sources = nlohmann::json::array();
        for (const SourceLimits& s : kLaserSources) sources.push_back(s.name);
        if (a->json) {
          nlohmann::json list = nlohmann::json::array();
          for (const auto& b : boards) {
            char id[16];
            std::snprintf(id, sizeof id, "%04x:%04x", b.vendor_id, b.product_id);
            list.push_back({{"bus", b.bus},
                            {"address", b.address},
                            {"port", b.port_path},
                            {"usb_id", id},
                            {"serial", b.serial ? nlohmann::json(*b.serial) : nlohmann::json(nullptr)},
                            {"device", b.serial ? nlohmann::json("lmc:" + *b.serial) : nlohmann::json(nullptr)},
                            {"usable", b.usable},
                            {"sources", sources},
                            {"note", b.note}});
          }
          std::cout << nlohmann::json{{"boards", list}}.dump() << "\n";
          return 0;
        }
        if (boards.empty()) {
          std::cout << "no LMC board found (USB 9588:9899)\n";
          return 0;
        }
        for (const auto& b : boards) {
          std::printf("bus %03d address %03d  port %-8s  ", b.bus, b.address, b.port_path.c_str());
          if (b.serial) std::printf("serial %s  (--device lmc:%s)", b.serial->c_str(), b.serial->c_str());
          else std::printf("serial ?");
          if (!b.note.empty()) std::printf("  %s", b.note.c_str());
          std::printf("\n");
        }
        // The source is not the board's to tell: the pen says which words to send.
        std::printf("laser sources: %s — the pen's --source (a job file pen's \"source\"), fiber unless set; "
                    "the board does not report which is wired\n",
                    laser_source_names().c_str());
        return 0;
      });
}

}  // namespace mark::cli
