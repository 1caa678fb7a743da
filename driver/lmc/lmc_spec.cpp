#include "driver/lmc/lmc_spec.hpp"

#include "driver/device_error.hpp"
#include "driver/lmc/codec.hpp"
#include "driver/lmc/emulated_board.hpp"

namespace mark::lmc {

std::optional<LmcSpec> parse_lmc_spec(std::string_view spec, std::string_view what) {
  const auto refuse = [&](const char* problem) {
    const std::string named = what.empty() ? "" : std::string(what) + " ";
    throw DeviceError(named + "'" + std::string(spec) + "'" + problem +
                      " (use lmc, lmc:SERIAL with the serial `marker devices` lists, "
                      "lmc-capture:FILE, or lmc-emulated[:VARIANT])");
  };
  LmcSpec s;
  if (spec == "lmc") return s;
  if (spec.starts_with("lmc-capture:")) {
    s.capture = true;
    s.file = std::string(spec.substr(12));
    if (s.file.empty()) refuse(": no file");
    return s;
  }
  if (spec == "lmc-emulated") {
    s.emulated = true;
    return s;
  }
  if (spec.starts_with("lmc-emulated:")) {
    s.emulated = true;
    s.variant = std::string(spec.substr(13));
    for (const BoardVariant& v : board_variants())
      if (v.name == s.variant) return s;
    std::string known;
    for (const BoardVariant& v : board_variants()) known += (known.empty() ? "" : ", ") + std::string(v.name);
    refuse((": no emulated board variant '" + s.variant + "' (known: " + known + ")").c_str());
  }
  if (spec.starts_with("lmc:")) {
    s.serial = std::string(spec.substr(4));
    if (!parse_serial(s.serial)) refuse(": a board serial is 1 to 8 hex digits");
    return s;
  }
  if (spec.starts_with("lmc")) refuse(" is malformed");
  return std::nullopt;
}

}  // namespace mark::lmc
