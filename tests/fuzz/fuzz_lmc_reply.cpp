// libFuzzer target for the LMC reply decoder and the codec's decoding side: any bytes either
// decode (exactly 8) or are refused with ReplyError; a decoded reply encodes back to the same
// bytes; its serial string parses back to its data words; and any 12 bytes decode to a command
// word that describe() can name, known opcode or not, with every axis map and polygon unit.
#include <cstdint>
#include <cstring>
#include <span>

#include "driver/lmc/codec.hpp"
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
  // Serial parsing of arbitrary text.
  if (size <= 16) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    if (const auto w = parse_serial(text); w && (text.empty() || text.size() > 8))
      broken("parse_serial accepted an empty or over-long serial");
  }
  return 0;
}
