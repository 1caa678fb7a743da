#include "marker/limits/pen_settings.hpp"

#include <algorithm>

namespace mark {
namespace {

bool listed(std::span<const SettingRef> list, const SettingRef& s) {
  return std::find(list.begin(), list.end(), s) != list.end();
}

}  // namespace

std::optional<std::string> pen_setting_unread(const SettingRef& s, std::string_view corner, bool lookahead) {
  const auto only = [&](std::string_view strategy) -> std::optional<std::string> {
    if (corner == strategy) return std::nullopt;
    return "only a pen with corner " + std::string(strategy) + " reads it (this pen's corner is " +
           std::string(corner) + ")";
  };
  if (listed(kDelaysPenSettings, s)) return only("delays");
  if (listed(kBlankingPenSettings, s)) return only("blanking");
  // The lag the delays and run-ins are sized for: a pen with no corner strategy sizes nothing.
  if (s == SettingRef{&kTrackingError} && corner == "none")
    return std::string("only a pen with corner blanking or delays reads it (this pen's corner is none)");
  if (listed(kLookaheadPenSettings, s) && !lookahead)
    return std::string("only the look-ahead planner reads it (give --lookahead or --feed-forward)");
  return std::nullopt;
}

}  // namespace mark
