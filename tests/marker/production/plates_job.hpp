#pragma once
// A production job whose text takes its rows from a data list: plates.csv's two VINs, each
// followed by the serial counted from 41 ("VIN-A 000041", then "VIN-B 000042"). Shared by the
// tests that check which row the next part takes (job check --preview, the station's PREVIEW).
#include <filesystem>
#include <fstream>

namespace mark::test {

inline constexpr const char* kPlatesJob = R"({
    "format": "marker-job/1", "head": "SL10", "time_zone": "UTC",
    "data": {"file": "plates.csv"},
    "counters": {"serial": {"start": 41, "width": 6}},
    "pens": {"fine": {"speed_mm_s": 800, "power_pct": 100, "frequency_khz": 40}},
    "objects": [{"name": "sn", "pen": "fine", "template": "{col:vin} {serial}", "height_mm": 3, "x_mm": -10, "y_mm": 0}]
  })";

// Writes the list, plates.csv, into `dir`: the job beside it names it relative to itself.
inline void write_plates_list(const std::filesystem::path& dir) {
  std::ofstream(dir / "plates.csv") << "vin\nVIN-A\nVIN-B\n";
}

}  // namespace mark::test
