#pragma once
// `--device lmc-capture:FILE`: the exact bytes the driver would send to endpoint 0x02, written
// to a file instead of a board, for offline inspection. One record per transfer: the byte 'S'
// and a 12-byte single command, or the byte 'L' and a 3072-byte list packet; nothing else (no
// header, no replies). Status replies are simulated as READY and not BUSY; GetSerialNo answers
// 00000000, GetPositionXY the field centre. The file is written whole on flush() — to FILE.tmp,
// then renamed — so a reader never sees half a capture. Thread-safe: a device's abort() on
// another thread writes its stop sequence while the job's thread may be flushing.
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include "driver/lmc/link.hpp"

namespace mark::lmc {

class CaptureLink : public LmcLink {
 public:
  explicit CaptureLink(std::string path);
  ~CaptureLink() override;  // a last flush, errors swallowed (call flush() to see them)

  void write(std::span<const std::uint8_t> bytes) override;
  std::array<std::uint8_t, kReplyBytes> read() override;
  void flush() override;
  std::string name() const override { return "capture " + path_; }
  bool simulated_replies() const override { return true; }

  std::size_t records() const;

 private:
  std::string path_;
  mutable std::mutex mutex_;  // everything below
  std::vector<std::uint8_t> bytes_;
  std::size_t records_ = 0;
  std::uint16_t last_opcode_ = 0;
  bool dirty_ = false;
};

struct CaptureRecord {
  bool packet = false;       // 'L' (else 'S')
  std::vector<Word> words;   // 1 for 'S', 256 for 'L'
};

// Parses a capture file's bytes; throws DeviceError naming the offset of anything malformed.
std::vector<CaptureRecord> parse_capture(std::span<const std::uint8_t> bytes,
                                         const std::string& source);
std::vector<CaptureRecord> read_capture(const std::string& path);

}  // namespace mark::lmc
