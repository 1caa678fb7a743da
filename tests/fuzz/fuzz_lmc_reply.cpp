// libFuzzer target for the LMC reply decoder and the codec's decoding side: any bytes either
// decode (exactly 8) or are refused with ReplyError; a decoded reply encodes back to the same
// bytes; its serial string parses back to its data words; and any 12 bytes decode to a command
// word that describe() can name, known opcode or not, with every axis map and polygon unit; the
// device names (`lmc`, `lmc:SERIAL`, `lmc-capture:FILE`, `lmc-emulated[:VARIANT]`) and laser
// source names parse to what they say or are refused, never anything else; and the masked link
// lets no word through that could fire the laser.
#include <cstdint>
#include <cstring>
#include <span>

#include "driver/laser_source.hpp"
#include "driver/lmc/codec.hpp"
#include "driver/lmc/emulated_board.hpp"
#include "driver/lmc/lmc_spec.hpp"
#include "driver/lmc/masked_link.hpp"
#include "fuzz_check.hpp"

using mark::fuzz::broken;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace mark::lmc;
  const std::span<const std::uint8_t> bytes(data, size);
  try {
    const Reply r = decode_reply(bytes);
    if (size != kReplyBytes) broken("a reply of the wrong length was accepted");
    const auto back = encode_reply(r);
    if (std::memcmp(back.data(), data, kReplyBytes) != 0) broken("reply does not round-trip");
    const std::string serial = serial_string(r);
    const auto words = parse_serial(serial);
    if (serial.size() != 8 || !words || (*words)[0] != r.w[1] || (*words)[1] != r.w[2])
      broken("serial string does not round-trip");
  } catch (const ReplyError&) {
    if (size == kReplyBytes) broken("an 8-byte reply was refused");
  }
  // Command words: every 12 bytes of the input, described under each unit setting.
  for (std::size_t at = 0; at + kCommandBytes <= size; at += kCommandBytes) {
    const Word w = load(data + at);
    for (int variant = 0; variant < 4; ++variant) {
      const FieldUnits u(110, AxisMap{(variant & 1) != 0, (variant & 2) != 0, false},
                         variant < 2 ? PolygonDelayUnit::ten_us : PolygonDelayUnit::signed_us);
      if (describe(w, u).empty()) broken("describe() returned nothing");
    }
  }
  // Device and source names.
  if (size <= 64) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
      if (const auto spec = parse_lmc_spec(text)) {
        if (spec->capture && spec->file.empty()) broken("a capture without a file");
        if (!spec->capture && !spec->emulated && !spec->serial.empty() && !parse_serial(spec->serial))
          broken("a serial that does not parse");
        if (spec->emulated) with_variant({}, spec->variant);  // throws for an unknown one
        if (!text.starts_with("lmc")) broken("a device name not starting with lmc");
      }
    } catch (const mark::DeviceError&) {
      if (!text.starts_with("lmc")) broken("a name that is not an LMC device was refused as one");
    }
    if (const auto source = mark::parse_laser_source(text); source && mark::to_string(*source) != text)
      broken("a laser source name that does not round-trip");
  }
  // The masked link: whatever 12-byte words come, none that would set the laser bit, open the
  // oscillator or enable the laser reaches the link behind it.
  {
    struct Sink : LmcLink {
      void write(std::span<const std::uint8_t> b) override {
        for (std::size_t at = 0; at + kCommandBytes <= b.size(); at += kCommandBytes) {
          const Word w = load(b.data() + at);
          const auto op = static_cast<Op>(w.opcode());
          if (((op == Op::WritePort || op == Op::ListWritePort) && (w.p(1) & 1)) ||
              ((op == Op::FiberSetMo || op == Op::FiberOpenMO) && w.p(1)) || op == Op::EnableLaser ||
              op == Op::LaserSignalOn || op == Op::LaserOnPoint)
            broken("the masked link let a firing word through");
        }
      }
      std::array<std::uint8_t, kReplyBytes> read() override { return {}; }
      std::string name() const override { return "fuzz"; }
    } sink;
    MaskedLink masked(sink, 0);
    for (std::size_t at = 0; at + kCommandBytes <= size; at += kCommandBytes) {
      try {
        masked.write(bytes.subspan(at, kCommandBytes));
      } catch (const LinkError&) {
      }
    }
    if (size >= kPacketBytes) {
      try {
        masked.write(bytes.first(kPacketBytes));
      } catch (const LinkError&) {
      }
    }
  }
  // Serial parsing of arbitrary text.
  if (size <= 16) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    if (const auto w = parse_serial(text); w && (text.empty() || text.size() > 8))
      broken("parse_serial accepted an empty or over-long serial");
  }
  return 0;
}
