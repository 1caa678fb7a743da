#pragma once
// EzCad field-correction files (.cor) for the LMC board: a 65 × 65 grid of (dx, dy) corrections
// in board units, uploaded with WriteCorTable(1) and 4225 WriteCorLine (galvo.md §1.6). Two
// formats exist:
// - "LMC1COR_1.0": a UTF-16LE label (22 bytes), 2 bytes, a header of 63 float64 (the lens scale
//   is #43), then 4225 (dx, dy) float64 pairs from offset 0x210;
// - the older one: 22 bytes of label, 6 bytes, the scale as one float64 at 0x1C, then 4225
//   (dx, dy) int32 pairs from offset 0x24.
// Every delta is checked to fit the board's sign-magnitude word (|d| ≤ 32767); anything else —
// a short file, a NaN, a delta that would wrap — is refused with the entry and the value.
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "driver/device_error.hpp"

namespace mark::lmc {

inline constexpr int kCorGrid = 65;
inline constexpr std::size_t kCorEntries = kCorGrid * kCorGrid;

struct CorrectionTable {
  enum class Format { lmc1cor_float, legacy_int };
  Format format = Format::legacy_int;
  std::string source;  // the file it came from, for messages
  // The file's lens scale as EzCad wrote it: board units per mm, so the lens it was made for
  // is 65536 / scale mm (meerk40t sets its lens size so: balormk/gui/balorconfig.py,
  // on_corfile_changed).
  double scale = 0;
  double lens_mm() const { return scale > 0 ? 65536.0 / scale : 0; }
  // (dx, dy) per grid point as the board takes them: sign-magnitude words.
  std::vector<std::array<std::uint16_t, 2>> entries;
};

// How far the lens field may differ from the one the table was made for: the table's deltas
// are in board units of its own lens, so a table for a 70 mm lens on a 110 mm field corrects
// the wrong places by the wrong amounts.
inline constexpr double kCorLensTolerance = 0.001;  // relative

// Refuses a table whose lens differs from `field_mm` by more than kCorLensTolerance, or whose
// scale gives no lens at all, naming both sizes. Throws CorFileError.
void check_cor_lens(const CorrectionTable& table, double field_mm);

class CorFileError : public DeviceError {
 public:
  using DeviceError::DeviceError;
};

// Parses a .cor file's bytes; `source` names it in errors.
CorrectionTable parse_cor(std::span<const std::uint8_t> bytes, const std::string& source);
// Reads and parses a file.
CorrectionTable read_cor_file(const std::string& path);

}  // namespace mark::lmc
