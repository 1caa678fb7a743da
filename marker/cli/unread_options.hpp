#pragma once
// Options that nothing in this run reads are refused, not accepted and ignored: a user who gives
// --polygon-delay-us to a blanking pen, --hatch-spacing to a text without a fill or --cor to the
// simulated scanner believes the mark got it. Each refusal is one line naming the option and
// what would make it apply: "--accel does not apply: only the look-ahead planner reads it (give
// --lookahead or --feed-forward)". Job files refuse their keys with the same reasons
// (marker/limits/pen_settings.hpp's pen_setting_unread).
#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "marker/limits/setting.hpp"

namespace mark::cli {

// Whether the option of `setting` (after `prefix`, as add_setting registered it) was given.
bool given(const CLI::App& app, const SettingRef& setting, std::string_view prefix = {});

// Throws InputError "FLAG does not apply: WHY" for the first of `settings` given for which
// `unread` names a reason.
void refuse_unread(const CLI::App& app, std::span<const SettingRef> settings,
                   const std::function<std::optional<std::string>(const SettingRef&)>& unread,
                   std::string_view prefix = {});
// The same when none of `settings` is read in this run (`read` false), for one reason.
void refuse_unread(const CLI::App& app, std::span<const SettingRef> settings, bool read, std::string_view why,
                   std::string_view prefix = {});

}  // namespace mark::cli
