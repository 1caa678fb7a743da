#include "driver/lmc/capture_link.hpp"

#include <cstdio>
#include <fstream>
#include <iterator>

namespace mark::lmc {

CaptureLink::CaptureLink(std::string path) : path_(std::move(path)) {
  if (path_.empty()) throw DeviceError("lmc-capture: no file name (use --device lmc-capture:FILE)");
}

CaptureLink::~CaptureLink() {
  try {
    flush();
  } catch (...) {
  }
}

void CaptureLink::write(std::span<const std::uint8_t> bytes) {
  if (bytes.size() != kCommandBytes && bytes.size() != kPacketBytes)
    throw LinkError(LinkFailure::io, "lmc-capture: a transfer of " + std::to_string(bytes.size()) +
                                         " bytes (the board takes 12 or 3072)");
  std::lock_guard lock(mutex_);
  bytes_.push_back(bytes.size() == kCommandBytes ? 'S' : 'L');
  bytes_.insert(bytes_.end(), bytes.begin(), bytes.end());
  if (bytes.size() == kCommandBytes) last_opcode_ = load(bytes.data()).opcode();
  ++records_;
  dirty_ = true;
}

std::size_t CaptureLink::records() const {
  std::lock_guard lock(mutex_);
  return records_;
}

std::array<std::uint8_t, kReplyBytes> CaptureLink::read() {
  std::lock_guard lock(mutex_);
  Reply r;
  if (last_opcode_ == static_cast<std::uint16_t>(Op::GetPositionXY)) r.w[1] = r.w[2] = 0x8000;
  r.w[3] = status::ready;  // READY, not BUSY
  return encode_reply(r);
}

void CaptureLink::flush() {
  std::lock_guard lock(mutex_);
  if (!dirty_) return;
  const std::string tmp = path_ + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw DeviceError("lmc-capture: cannot write " + tmp);
    out.write(reinterpret_cast<const char*>(bytes_.data()), std::streamsize(bytes_.size()));
    out.flush();
    if (!out) {
      std::remove(tmp.c_str());
      throw DeviceError("lmc-capture: writing " + tmp + " failed");
    }
  }
  if (std::rename(tmp.c_str(), path_.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw DeviceError("lmc-capture: cannot rename " + tmp + " to " + path_);
  }
  dirty_ = false;
}

std::vector<CaptureRecord> parse_capture(std::span<const std::uint8_t> b, const std::string& source) {
  std::vector<CaptureRecord> out;
  std::size_t i = 0;
  while (i < b.size()) {
    const std::uint8_t tag = b[i];
    const std::size_t n = tag == 'S' ? kCommandBytes : tag == 'L' ? kPacketBytes : 0;
    if (n == 0)
      throw DeviceError(source + ": offset " + std::to_string(i) + ": record tag " +
                        std::to_string(tag) + " is neither 'S' nor 'L'");
    if (b.size() - i - 1 < n)
      throw DeviceError(source + ": offset " + std::to_string(i) + ": a '" + char(tag) +
                        "' record needs " + std::to_string(n) + " bytes, " +
                        std::to_string(b.size() - i - 1) + " remain");
    CaptureRecord r;
    r.packet = tag == 'L';
    for (std::size_t k = 0; k < n; k += kCommandBytes) r.words.push_back(load(b.data() + i + 1 + k));
    out.push_back(std::move(r));
    i += 1 + n;
  }
  return out;
}

std::vector<CaptureRecord> read_capture(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DeviceError("lmc-capture: cannot open " + path);
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parse_capture(bytes, path);
}

}  // namespace mark::lmc
