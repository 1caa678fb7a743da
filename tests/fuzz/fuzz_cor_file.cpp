// libFuzzer target for the EzCad .cor reader (both formats) and the capture-file reader: either
// the input is refused with the reader's error, or the result is what the board and the dump can
// trust — exactly 65 × 65 deltas that are valid sign-magnitude words (|d| ≤ 32767, re-encoding
// to the same word), a finite-or-reported scale; capture records that account for every byte.
#include <cstdint>
#include <span>

#include "driver/lmc/capture_link.hpp"
#include "driver/lmc/codec.hpp"
#include "driver/lmc/cor_file.hpp"
#include "fuzz_check.hpp"

using mark::fuzz::broken;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace mark::lmc;
  const std::span<const std::uint8_t> bytes(data, size);
  try {
    const CorrectionTable t = parse_cor(bytes, "fuzz.cor");
    if (t.entries.size() != kCorEntries) broken("a table without 65 × 65 entries");
    for (const auto& e : t.entries)
      for (std::uint16_t w : e) {
        const std::int32_t d = decode_cor_delta(w);
        if (d < -32767 || d > 32767 || encode_cor_delta(d) != w) broken("a delta word that does not round-trip");
      }
  } catch (const CorFileError&) {
  }
  try {
    std::size_t total = 0;
    for (const CaptureRecord& r : parse_capture(bytes, "fuzz.lmc")) {
      if (r.words.size() != (r.packet ? kCommandsPerPacket : 1u)) broken("a capture record of the wrong size");
      total += 1 + r.words.size() * kCommandBytes;
    }
    if (total != size) broken("capture records do not account for every byte");
  } catch (const mark::DeviceError&) {
  }
  return 0;
}
