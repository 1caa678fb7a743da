#pragma once
// Every table of settings (setting.hpp), in the order `marker options` lists them. A table is
// added here and nowhere else; the settings test fails for a command-line option or a job-file
// key that none of them declares, and for a docs table that differs from its table.
#include <span>
#include <string_view>

#include "marker/limits/cnc_settings.hpp"
#include "marker/limits/code_settings.hpp"
#include "marker/limits/device_settings.hpp"
#include "marker/limits/fill_settings.hpp"
#include "marker/limits/gravure_settings.hpp"
#include "marker/limits/head_settings.hpp"
#include "marker/limits/layout_settings.hpp"
#include "marker/limits/marking_settings.hpp"
#include "marker/limits/peen_settings.hpp"
#include "marker/limits/pen_settings.hpp"
#include "marker/limits/production_settings.hpp"
#include "marker/limits/station_settings.hpp"

namespace mark {

inline constexpr const SettingTable* kSettingTables[] = {
    &kHeadSettings,    &kPenSettings,    &kLayoutSettings, &kFillSettings,    &kCodeSettings,
    &kMarkingSettings, &kDeviceSettings, &kObjectSettings, &kJobSettings,     &kCounterSettings,
    &kNewCodeSettings, &kRunSettings,     &kPeenSettings,   &kCncSettings,    &kGravureSettings, &kStationSettings};

// The table with this id, or nullptr.
const SettingTable* find_setting_table(std::string_view id);

// The table as a Markdown table: | option | job key | range | default | meaning |.
std::string markdown_table(const SettingTable& table);

}  // namespace mark
