// The LMC codec: the golden rectangle of galvo.md §1.9 byte for byte, the one table's
// consistency, every unit encoder against hand-computed words, reply decoding.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "driver/lmc/codec.hpp"
#include "driver/lmc/job_encoder.hpp"
#include "tests/driver/lmc/lmc_test_support.hpp"

namespace mark::lmc {
namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

// meerk40t's test vector with EzCad's (its default) axes: the same bytes but for one word, the
// JumpDelay(0) every list carries (lmc_test_support.hpp).
TEST(LmcCodec, GoldenRectangleByteForByte) {
  const FieldUnits units = test::golden_units();
  std::vector<std::vector<std::uint8_t>> packets;
  JobEncoder enc(units, [&](const ListPacket& p, const PacketInfo& info) {
    packets.emplace_back(p.bytes().begin(), p.bytes().end());
    EXPECT_TRUE(info.last);
    EXPECT_EQ(info.commands_complete, 5u);
  });
  const BoardPen pen = encode_pen(test::golden_pen(), 0, units);
  enc.start_list(0.008, 0x0001);
  enc.apply_pen(pen);
  const auto commands = test::golden_rectangle_commands();
  for (std::size_t i = 0; i < commands.size(); ++i) enc.add(commands[i], i);
  enc.finish(commands.size());

  ASSERT_EQ(packets.size(), 1u);
  const auto expected = test::packet_bytes(test::golden_rectangle_words());
  ASSERT_EQ(packets[0].size(), kPacketBytes);
  for (std::size_t i = 0; i < kPacketBytes; ++i)
    ASSERT_EQ(packets[0][i], expected[i]) << "byte " << i << " (command " << i / 12 << ": "
                                          << describe(load(packets[0].data() + i / 12 * 12), units)
                                          << ")";
  // Word for word meerk40t's, with the one JumpDelay taken out.
  std::vector<Word> ours;
  for (std::size_t i = 0; i < 18; ++i) ours.push_back(load(packets[0].data() + 12 * i));
  EXPECT_EQ(ours[10], word(Op::JumpDelay, 0, 0));
  ours.erase(ours.begin() + 10);
  EXPECT_EQ(ours, test::meerk40t_rectangle_words());
  EXPECT_EQ(enc.figures().list_commands, 18u);
  EXPECT_EQ(enc.figures().moves, 5u);
  EXPECT_EQ(enc.figures().packets, 1u);
  // The estimate: jump √(20852² + 20853²) units at 1191 units/ms, four sides of 5958 units at
  // 8 units/ms, three right-angle corners of 100 µs polygon delay, the open-MO delay and the mark
  // delay.
  EXPECT_NEAR(enc.figures().estimated_s,
              std::hypot(20852.0, 20853.0) / 1191e3 + 4 * 5958.0 / 8e3 + 3 * 100e-6 + 0.008 + 0.0003, 1e-9);
}

TEST(LmcCodec, TableIsConsistent) {
  std::set<std::uint16_t> ops;
  std::set<std::string_view> names;
  for (const CommandSpec& s : kCommands) {
    const auto op = static_cast<std::uint16_t>(s.op);
    EXPECT_TRUE(ops.insert(op).second) << s.name;
    EXPECT_TRUE(names.insert(s.name).second) << s.name;
    EXPECT_EQ(find_command(op), &s) << s.name;
    EXPECT_EQ(command_name(op), s.name);
    // List commands are never answered; every single command is, except WriteCorLine.
    if (is_list(op)) EXPECT_FALSE(s.reply) << s.name;
    else EXPECT_EQ(s.reply, s.op != Op::WriteCorLine) << s.name;
    EXPECT_LE(s.count, 5);
  }
  EXPECT_EQ(find_command(0x8099), nullptr);
  EXPECT_EQ(find_command(0x1234), nullptr);
  EXPECT_EQ(command_name(0x8099), "unknown list command");
}

TEST(LmcCodec, FieldUnitsTruncateAroundTheCentre) {
  const FieldUnits u(110);
  EXPECT_NEAR(u.units_per_mm(), 65535.0 / 110, 1e-12);
  EXPECT_EQ(u.point(0, 0), (std::array<std::uint16_t, 2>{0x8000, 0x8000}));
  EXPECT_EQ(u.point(35, -35), (std::array<std::uint16_t, 2>{0xD174, 0x2E8B}));
  EXPECT_EQ(u.point(55, -55), (std::array<std::uint16_t, 2>{0xFFFF, 0x0000}));  // the edges
  const std::string e = error_of([&] { u.point(55.01, 3); });
  EXPECT_NE(e.find("(55.0100, 3.0000) mm lies outside the 110 mm field"), std::string::npos) << e;
  EXPECT_NE(error_of([&] { u.point(std::nan(""), 0); }).find("outside"), std::string::npos);
  // Round trip within one unit (the truncation).
  for (double x : {-54.9, -12.345, 0.001, 7.5, 54.99}) {
    const auto w = u.point(x, -x);
    const auto back = u.field_point(w[0], w[1]);
    EXPECT_GE(x - back[0], 0.0);
    EXPECT_LT(x - back[0], 1 / u.units_per_mm());
  }
  EXPECT_NE(error_of([] { FieldUnits bad(0); }).find("lens field 0 mm"), std::string::npos);
}

TEST(LmcCodec, AxisMapSwapsAndMirrors) {
  const FieldUnits swapped(110, AxisMap{true, false, false});
  EXPECT_EQ(swapped.point(35, -35), (std::array<std::uint16_t, 2>{0x2E8B, 0xD174}));
  const FieldUnits flipped(110, AxisMap{false, true, true});
  EXPECT_EQ(flipped.point(-35, 35), (std::array<std::uint16_t, 2>{0xD174, 0x2E8B}));
  const FieldUnits both(110, AxisMap{true, true, false});
  const auto w = both.point(10, 20);
  const auto back = both.field_point(w[0], w[1]);
  EXPECT_NEAR(back[0], 10, 0.002);
  EXPECT_NEAR(back[1], 20, 0.002);
}

TEST(LmcCodec, UnitEncoders) {
  const FieldUnits u(110);
  EXPECT_EQ(encode_speed(2000, u), 0x04A7);  // 1191.5 units/ms, truncated
  EXPECT_EQ(encode_speed(15, u), 8);
  EXPECT_NEAR(decode_speed(1191, u), 1191 * 110 / 65.535, 1e-9);  // 1999.08 mm/s
  const std::string slow = error_of([&] { encode_speed(1, u, "pen 0: mark speed"); });
  EXPECT_NE(slow.find("pen 0: mark speed 1 mm/s is outside"), std::string::npos) << slow;
  EXPECT_NE(slow.find("allowed 1.678 .. 110000 mm/s"), std::string::npos) << slow;
  EXPECT_NE(error_of([&] { encode_speed(2e5, u); }).find("outside"), std::string::npos);

  EXPECT_EQ(encode_signed_us(100e-6), (std::array<std::uint16_t, 2>{100, 0}));
  EXPECT_EQ(encode_signed_us(-50e-6), (std::array<std::uint16_t, 2>{50, 0x8000}));
  EXPECT_DOUBLE_EQ(decode_signed_us(50, 0x8000), -50e-6);
  EXPECT_NE(error_of([] { encode_signed_us(0.07); }).find("70000 µs does not fit"), std::string::npos);

  EXPECT_EQ(encode_polygon_delay(100e-6, PolygonDelayUnit::ten_us), (std::array<std::uint16_t, 2>{10, 0}));
  EXPECT_EQ(encode_polygon_delay(100e-6, PolygonDelayUnit::signed_us), (std::array<std::uint16_t, 2>{100, 0}));
  EXPECT_NE(error_of([] { encode_polygon_delay(-1e-5, PolygonDelayUnit::ten_us); }).find("does not fit"),
            std::string::npos);

  EXPECT_EQ(encode_time_10us(0.008), 800);
  EXPECT_EQ(encode_time_10us(300e-6), 30);
  EXPECT_NE(error_of([] { encode_time_10us(0.7, 60000, "dwell"); }).find("dwell 700000 µs"), std::string::npos);

  EXPECT_EQ(encode_period_50ns(20), 1000);
  EXPECT_EQ(encode_period_50ns(30), 667);
  EXPECT_EQ(encode_period_100ns(20), 500);
  EXPECT_NE(error_of([] { encode_period_50ns(0); }).find("0 kHz is not a frequency"), std::string::npos);
  EXPECT_NE(error_of([] { encode_period_50ns(0.1); }).find("does not fit"), std::string::npos);

  EXPECT_EQ(encode_power_12bit(100), 0x0FFF);
  EXPECT_EQ(encode_power_12bit(50), 2048);
  EXPECT_EQ(encode_power_12bit(0), 0);
  EXPECT_NE(error_of([] { encode_power_12bit(101); }).find("101 % is outside 0 .. 100 %"), std::string::npos);

  EXPECT_EQ(encode_pulse_width_ns(200), 200);
  EXPECT_EQ(encode_cor_delta(5), 5);
  EXPECT_EQ(encode_cor_delta(-5), 0x8005);
  EXPECT_EQ(decode_cor_delta(0x8005), -5);
  EXPECT_NE(error_of([] { encode_cor_delta(-32768); }).find("-32768 units"), std::string::npos);

  EXPECT_EQ(segment_distance({0x8000, 0x8000}, {0xD174, 0x2E8B}), 0x7331);
  EXPECT_EQ(segment_distance({0, 0}, {0xFFFF, 0xFFFF}), 0xFFFF);  // clamped
}

TEST(LmcCodec, TableDrivenEncoderAndDecoder) {
  const FieldUnits u(110);
  EXPECT_EQ(encode(Op::SetStandby, {2000, 20}, u), word(Op::SetStandby, 2000, 20));
  EXPECT_EQ(encode(Op::JumpTo, {35, -35, 0, 0x7331}, u), word(Op::JumpTo, 0xD174, 0x2E8B, 0, 0x7331));
  EXPECT_EQ(encode(Op::LaserOnDelay, {-100e-6}, u), word(Op::LaserOnDelay, 100, 0x8000));
  EXPECT_EQ(encode(Op::MarkSpeed, {15}, u), word(Op::MarkSpeed, 8));
  EXPECT_EQ(encode(Op::QSwitchPeriod, {20}, u), word(Op::QSwitchPeriod, 1000));
  EXPECT_EQ(encode(Op::PolygonDelay, {100e-6}, u), word(Op::PolygonDelay, 10));
  EXPECT_NE(error_of([&] { encode(Op::SetStandby, {1}, u); }).find("takes 2 parameters, not 1"),
            std::string::npos);
  EXPECT_NE(error_of([&] { encode(Op::SetStandby, {70000, 1}, u); }).find("SetStandby standby1"),
            std::string::npos);

  const Word w = word(Op::MarkTo, 0xD174, 0x45D1, 0, 0x1746);
  const auto v = decode_params(w, *find_command(w.opcode()), u);
  EXPECT_NEAR(v[0], 35, 0.002);
  EXPECT_NEAR(v[1], -25, 0.002);
  EXPECT_EQ(v[3], 0x1746);
  EXPECT_EQ(describe(w, u), "MarkTo x=35 mm y=-25 mm angle=0 distance=5958");
  EXPECT_EQ(describe(word(Op::LaserOffDelay, 100, 0x8000), u), "LaserOffDelay delay=-100 µs");
  EXPECT_EQ(describe(word(Op::QSwitchPeriod, 1000), u), "QSwitchPeriod period=20 kHz");
  EXPECT_EQ(describe(Word{{0x8099, 1, 2, 3, 4, 5}}, u),
            "0x8099 (unknown list command) 0001 0002 0003 0004 0005");
}

TEST(LmcCodec, WordsAndPackets) {
  const Word w = word(Op::JumpTo, 0xD174, 0x2E8B, 0, 0x7331);
  const auto b = bytes(w);
  EXPECT_EQ(b, (std::array<std::uint8_t, 12>{0x01, 0x80, 0x74, 0xD1, 0x8B, 0x2E, 0, 0, 0x31, 0x73, 0, 0}));
  EXPECT_EQ(load(b.data()), w);
  ListPacket p;
  EXPECT_TRUE(p.empty());
  for (std::size_t i = 0; i < kCommandsPerPacket; ++i)
    EXPECT_EQ(load(p.bytes().data() + 12 * i), word(Op::EndOfList)) << i;
  for (std::size_t i = 0; i < kCommandsPerPacket; ++i) p.push(w);
  EXPECT_TRUE(p.full());
  p.clear();
  EXPECT_EQ(load(p.bytes().data()), word(Op::EndOfList));
  // Refilled after a full packet: the words it does not use are padding again, not what the
  // full packet held there (clear() leaves them; bytes() pads).
  for (std::size_t i = 0; i < kCommandsPerPacket; ++i) p.push(w);
  p.clear();
  p.push(word(Op::MarkTo, 1, 2, 0, 3));
  EXPECT_EQ(load(p.bytes().data()), word(Op::MarkTo, 1, 2, 0, 3));
  for (std::size_t i = 1; i < kCommandsPerPacket; ++i)
    EXPECT_EQ(load(p.bytes().data() + 12 * i), word(Op::EndOfList)) << i;
}

// Mirrored and swapped axes: the words are the unmirrored ones reflected about 0x8000 and
// exchanged (the mirroring lives in the scales' signs).
TEST(LmcCodec, AxisMapMirrorsAndSwapsTheWords) {
  const FieldUnits plain(110);
  const auto p = plain.point(12.5, -3);
  const auto mirrored = [](std::uint16_t w) { return std::uint16_t(0x10000 - w); };
  EXPECT_EQ(FieldUnits(110, {false, true, false}).point(12.5, -3), (std::array{plain.point(-12.5, -3)[0], p[1]}));
  EXPECT_EQ(FieldUnits(110, {false, false, true}).point(12.5, -3), (std::array{p[0], plain.point(12.5, 3)[1]}));
  EXPECT_EQ(FieldUnits(110, {true, false, false}).point(12.5, -3), (std::array{p[1], p[0]}));
  EXPECT_EQ(FieldUnits(110, {true, true, true}).point(12.5, -3), (std::array{plain.point(12.5, 3)[1], plain.point(-12.5, -3)[0]}));
  // x·(−k) is (−x)·k to the bit, so a mirrored word is 0x10000 − w up to the truncation's side.
  EXPECT_NEAR(FieldUnits(110, {false, true, false}).point(12.5, -3)[0], mirrored(p[0]), 1);
}

TEST(LmcCodec, Replies) {
  const std::array<std::uint8_t, 8> raw{0x01, 0x00, 0x34, 0x12, 0xCD, 0xAB, 0x24, 0x00};
  const Reply r = decode_reply(raw);
  EXPECT_EQ(r.w, (std::array<std::uint16_t, 4>{1, 0x1234, 0xABCD, 0x0024}));
  EXPECT_TRUE(r.ready());
  EXPECT_TRUE(r.busy());
  EXPECT_FALSE(r.paused());
  EXPECT_EQ(encode_reply(r), raw);
  EXPECT_EQ(serial_string(r), "1234ABCD");
  EXPECT_EQ(parse_serial("1234abcd"), (std::array<std::uint16_t, 2>{0x1234, 0xABCD}));
  EXPECT_EQ(parse_serial("ab"), (std::array<std::uint16_t, 2>{0, 0xAB}));
  EXPECT_FALSE(parse_serial("12345678A"));
  EXPECT_FALSE(parse_serial("xyz"));
  EXPECT_FALSE(parse_serial(""));
  const std::array<std::uint8_t, 7> short_reply{};
  EXPECT_NE(error_of([&] { decode_reply(short_reply); }).find("reply of 7 bytes, expected 8"),
            std::string::npos);
}

TEST(LmcEncoder, SpeedsAndDelaysOnlyWhenTheyChange) {
  const FieldUnits units(110);
  std::vector<Word> words;
  JobEncoder enc(units, [&](const ListPacket& p, const PacketInfo&) {
    for (std::size_t i = 0; i < kCommandsPerPacket; ++i) words.push_back(load(p.bytes().data() + 12 * i));
  });
  DevicePen pen = test::golden_pen();
  pen.mark_speed_mm_s = 1000;
  pen.jump_delay_s = 200e-6;
  const BoardPen bp = encode_pen(pen, 0, units);
  enc.start_list(0, 1);
  enc.apply_pen(bp);
  // Two marks at the pen's speed: one MarkSpeed (from the pen); then a faster mark; then a
  // blanking line at 1000 mm/s (JumpSpeed 595, JumpDelay 0), a travel jump (back to 2000 mm/s
  // and 200 µs, preceded by the mark delay? no: the blanking line already ended the run).
  enc.add(DeviceCommand::jump_to(1, 1), 0);
  enc.add(DeviceCommand::mark_to(2, 1), 1);
  enc.add(DeviceCommand::mark_to(3, 1), 2);
  enc.add(DeviceCommand::mark_to(4, 1, 1500), 3);
  enc.add(DeviceCommand::jump_to(5, 1, 1000), 4);
  enc.add(DeviceCommand::jump_to(6, 6), 5);
  enc.add(DeviceCommand::mark_to(7, 6), 6);
  enc.add(DeviceCommand::mark_to(7, 6), 7);  // nowhere to go: dropped
  enc.add(DeviceCommand::jump_to(0, 0), 8);   // after a mark run: the mark delay first
  enc.add(DeviceCommand::dwell_for(1.0, false), 9);  // 100000 ticks: 65535 + 34465
  enc.add(DeviceCommand::dwell_for(0.7, true), 10);  // 70000 ticks: 60000 + 10000
  enc.finish(11);

  std::vector<std::uint16_t> ops;
  for (const Word& w : words) {
    if (w.opcode() == static_cast<std::uint16_t>(Op::EndOfList)) break;
    ops.push_back(w.opcode());
  }
  using O = Op;
  const std::vector<O> want = {
      O::ReadyMark, O::ListWritePort, O::JumpSpeed, O::QSwitchPeriod, O::MarkCurrent, O::MarkSpeed,
      O::LaserOnDelay, O::LaserOffDelay, O::PolygonDelay, O::JumpDelay,
      O::JumpTo, O::MarkTo, O::MarkTo, O::MarkSpeed, O::MarkTo,
      O::JumpSpeed, O::JumpDelay, O::JumpTo,
      O::JumpSpeed, O::JumpDelay, O::JumpTo,
      O::MarkSpeed, O::MarkTo,
      O::DelayTime, O::JumpTo,
      O::DelayTime, O::DelayTime, O::LaserOnPoint, O::LaserOnPoint};
  ASSERT_EQ(ops.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i)
    EXPECT_EQ(ops[i], static_cast<std::uint16_t>(want[i])) << "word " << i << ": " << describe(words[i], units);
  EXPECT_EQ(words[16], word(O::JumpDelay, 0, 0));
  EXPECT_EQ(words[15], word(O::JumpSpeed, 595));
  EXPECT_EQ(words[19], word(O::JumpDelay, 200, 0));
  EXPECT_EQ(words[23], word(O::DelayTime, 30));  // the mark delay
  EXPECT_EQ(words[25], word(O::DelayTime, 65535));
  EXPECT_EQ(words[26], word(O::DelayTime, 34465));
  EXPECT_EQ(words[27], word(O::LaserOnPoint, 60000));
  EXPECT_EQ(words[28], word(O::LaserOnPoint, 10000));
}

TEST(LmcEncoder, PacketsCarryWhatTheyComplete) {
  const FieldUnits units(110);
  std::vector<PacketInfo> infos;
  JobEncoder enc(units, [&](const ListPacket& p, const PacketInfo& i) {
    infos.push_back(i);
    EXPECT_TRUE(p.full() || i.last);
  });
  const BoardPen bp = encode_pen(test::golden_pen(), 0, units);
  enc.start_list(0.008, 1);
  enc.apply_pen(bp);  // 11 words so far
  for (int i = 0; i < 600; ++i) enc.add(DeviceCommand::mark_to(i % 2 ? 1 : 2, 0.001 * i), std::uint64_t(i));
  enc.finish(600);
  ASSERT_EQ(infos.size(), 3u);  // 11 + 600 + 2 (mark delay, EndOfList) = 613 words
  EXPECT_EQ(infos[0].commands_complete, 245u);  // words 11..255 are commands 0..244
  EXPECT_EQ(infos[1].commands_complete, 501u);
  EXPECT_EQ(infos[2].commands_complete, 600u);
  EXPECT_TRUE(infos[2].last);
  EXPECT_EQ(enc.figures().packets, 3u);
  EXPECT_EQ(enc.figures().list_commands, 613u);
}

// The span form (what LmcDevice::submit uses) puts out the same packets, with the same
// completion counts and estimates, as the commands added one by one: travel, blanking lines,
// marks at changing speeds, a pen switch mid-run, dwells, dropped moves, packet boundaries.
TEST(LmcEncoder, SpanGivesTheSameWordsAsOneByOne) {
  const FieldUnits units(110);
  DevicePen p0 = test::golden_pen();
  p0.jump_delay_s = 200e-6;
  DevicePen p1 = p0;
  p1.mark_speed_mm_s = 900;
  p1.laser.power_pct = 40;
  const std::vector<BoardPen> pens = {encode_pen(p0, 0, units),
                                      encode_pen(p1, 1, units)};
  std::vector<DeviceCommand> cs = {DeviceCommand::select_pen(0), DeviceCommand::jump_to(1, 1)};
  for (int i = 0; i < 700; ++i) {
    const double x = 1 + 0.01 * i;
    switch (i % 7) {
      case 0: cs.push_back(DeviceCommand::jump_to(x, 2, 1000 + i)); break;  // a run-in
      case 1: cs.push_back(DeviceCommand::mark_to(x, 2.5)); break;
      case 2: cs.push_back(DeviceCommand::mark_to(x, 2.5, 1500)); break;
      case 3: cs.push_back(DeviceCommand::mark_to(x, 2.5, 1500)); break;  // nowhere to go
      case 4: cs.push_back(DeviceCommand::jump_to(x, 3)); break;            // travel
      case 5: cs.push_back(i % 2 ? DeviceCommand::dwell_for(1e-4, true) : DeviceCommand::select_pen(1)); break;
      case 6: cs.push_back(i % 3 ? DeviceCommand::mark_to(x, 1) : DeviceCommand::select_pen(0)); break;
    }
  }
  struct Out {
    std::vector<std::vector<std::uint8_t>> packets;
    std::vector<PacketInfo> infos;
  };
  const auto encode = [&](bool span, Out& out) {
    JobEncoder enc(units, [&](const ListPacket& p, const PacketInfo& i) {
      out.packets.emplace_back(p.bytes().begin(), p.bytes().end());
      out.infos.push_back(i);
    });
    enc.start_list(0.008, 1);
    enc.apply_pen(pens[0]);
    if (span) {
      enc.add(cs, 0, pens);
    } else {
      for (std::size_t i = 0; i < cs.size(); ++i) {
        enc.add(cs[i], i);
        if (cs[i].op == DeviceOp::pen) enc.apply_pen(pens[cs[i].pen]);
      }
    }
    enc.finish(cs.size());
    return enc.figures();
  };
  Out one, all;
  const EncoderFigures f1 = encode(false, one), f2 = encode(true, all);
  ASSERT_GE(one.packets.size(), 4u);
  ASSERT_EQ(one.packets.size(), all.packets.size());
  for (std::size_t k = 0; k < one.packets.size(); ++k) {
    EXPECT_EQ(one.packets[k], all.packets[k]) << "packet " << k;
    EXPECT_EQ(one.infos[k].commands_complete, all.infos[k].commands_complete) << "packet " << k;
    EXPECT_DOUBLE_EQ(one.infos[k].estimated_s, all.infos[k].estimated_s) << "packet " << k;
  }
  EXPECT_EQ(f1.list_commands, f2.list_commands);
  EXPECT_EQ(f1.moves, f2.moves);
  EXPECT_EQ(f1.parameter_commands, f2.parameter_commands);
  EXPECT_GT(f1.parameter_commands, 200u);  // the speeds really changed along the way

  // A pen the span does not hold is refused, naming the command.
  JobEncoder enc(units, [](const ListPacket&, const PacketInfo&) {});
  enc.start_list(0, 1);
  const std::vector<DeviceCommand> bad = {DeviceCommand::select_pen(0), DeviceCommand::select_pen(2)};
  EXPECT_NE(error_of([&] { enc.add(bad, 40, pens); }).find("command 41 selects pen 2; the job has 2"),
            std::string::npos);
  // A move at the pen's speed before any pen: refused, not a crash.
  JobEncoder bare(units, [](const ListPacket&, const PacketInfo&) {});
  bare.start_list(0, 1);
  EXPECT_NE(error_of([&] { bare.add(DeviceCommand::mark_to(1, 1), 7); })
                .find("command 7 uses the pen's speed before any pen was applied"),
            std::string::npos);
}

TEST(LmcEncoder, PenRefusalsNameThePenAndTheValue) {
  const FieldUnits u(110);
  DevicePen p = test::golden_pen();
  p.laser.frequency_khz = 0;
  EXPECT_NE(error_of([&] { encode_pen(p, 2, u); })
                .find("lmc: pen 2: frequency 0 kHz is outside what a fiber source runs (Q-switched fiber: 1 .. 200 kHz)"),
            std::string::npos)
      << error_of([&] { encode_pen(p, 2, u); });
  p = test::golden_pen();
  p.laser_on_delay_s = 1;
  EXPECT_NE(error_of([&] { encode_pen(p, 3, u); }).find("pen 3: laser-on delay 1e+06 µs"),
            std::string::npos);
  // A pulse width only on a MOPA source; 0 (the source's own) on any.
  p = test::golden_pen();
  p.laser.pulse_width_ns = 200;
  EXPECT_NE(error_of([&] { encode_pen(p, 0, u); })
                .find("lmc: pen 0: pulse width 200 ns: a fiber source (Q-switched fiber) has no settable pulse width"),
            std::string::npos);
  p.laser.source = LaserSource::co2;
  p.laser.frequency_khz = 10;
  EXPECT_NE(error_of([&] { encode_pen(p, 1, u); }).find("pen 1: pulse width 200 ns: a co2 source"), std::string::npos);
  p.laser.source = LaserSource::mopa;
  EXPECT_EQ(encode_pen(p, 0, u).pulse_width, 200);
  p.laser.pulse_width_ns = 0;
  EXPECT_FALSE(encode_pen(p, 0, u).pulse_width);
}

// Each source's laser words, against meerk40t's formulas worked by hand (balormk/controller.py:
// fiber QSwitchPeriod = round(20000 / kHz), MarkCurrent = round(% × 4095 / 100); CO2 and UV
// MarkFreq = round(10000 / kHz), SetCo2FPK = round(2000 / kHz) twice, MarkPowerRatio =
// round(200 × % / kHz)); MOPA's pulse width in ns before them.
TEST(LmcEncoder, EachSourceGetsItsOwnWords) {
  const FieldUnits units(110);
  const auto preamble = [&](LaserSource source, double khz, double pct, double ns) {
    DevicePen p = test::golden_pen();
    p.laser = {pct, khz, ns, source};
    std::vector<Word> words;
    JobEncoder enc(units, [&](const ListPacket& pk, const PacketInfo&) {
      for (std::size_t i = 0; i < pk.used(); ++i) words.push_back(load(pk.bytes().data() + 12 * i));
    });
    enc.start_list(0, 1);
    enc.apply_pen(encode_pen(p, 0, units));
    enc.finish(0);
    // The laser words: between JumpSpeed (word 3) and MarkSpeed.
    std::vector<Word> laser;
    for (std::size_t i = 3; i < words.size() && words[i].opcode() != std::uint16_t(Op::MarkSpeed); ++i)
      laser.push_back(words[i]);
    return laser;
  };
  using W = std::vector<Word>;
  EXPECT_EQ(preamble(LaserSource::fiber, 20, 100, 0), (W{word(Op::QSwitchPeriod, 1000), word(Op::MarkCurrent, 4095)}));
  EXPECT_EQ(preamble(LaserSource::fiber, 30, 60, 0), (W{word(Op::QSwitchPeriod, 667), word(Op::MarkCurrent, 2457)}));
  EXPECT_EQ(preamble(LaserSource::mopa, 200, 60, 50),
            (W{word(Op::FiberYLPMPulseWidth, 50), word(Op::QSwitchPeriod, 100), word(Op::MarkCurrent, 2457)}));
  EXPECT_EQ(preamble(LaserSource::mopa, 200, 60, 0), (W{word(Op::QSwitchPeriod, 100), word(Op::MarkCurrent, 2457)}));
  EXPECT_EQ(preamble(LaserSource::co2, 20, 60, 0),
            (W{word(Op::MarkFreq, 500), word(Op::SetCo2Fpk, 100, 100), word(Op::MarkPowerRatio, 600)}));
  EXPECT_EQ(preamble(LaserSource::uv, 40, 30, 0),
            (W{word(Op::MarkFreq, 250), word(Op::SetCo2Fpk, 50, 50), word(Op::MarkPowerRatio, 150)}));
}

// A new list forgets everything: the same pen applied again sends every word again — JumpDelay
// too (a board keeps its registers across lists, but an earlier list may not have reached it).
TEST(LmcEncoder, EveryListSetsEverySetting) {
  const FieldUnits units(110);
  std::vector<std::vector<Word>> lists(1);
  JobEncoder enc(units, [&](const ListPacket& pk, const PacketInfo& info) {
    for (std::size_t i = 0; i < pk.used(); ++i) lists.back().push_back(load(pk.bytes().data() + 12 * i));
    if (info.last) lists.emplace_back();
  });
  const BoardPen pen = encode_pen(test::golden_pen(), 0, units);
  for (int k = 0; k < 2; ++k) {
    enc.start_list(0, 1);
    enc.apply_pen(pen);
    enc.add(DeviceCommand::jump_to(1, 1), 0);
    enc.add(DeviceCommand::mark_to(2, 1), 1);
    enc.finish(2);
  }
  ASSERT_EQ(lists.size(), 3u);
  // The same words, but for the jump's distance: the second starts where the first list left
  // the mirrors.
  ASSERT_EQ(lists[0].size(), lists[1].size());
  for (std::size_t i = 0; i < lists[0].size(); ++i) {
    Word a = lists[0][i], b = lists[1][i];
    if (a.opcode() == std::uint16_t(Op::JumpTo)) a.w[4] = b.w[4] = 0;
    EXPECT_EQ(a, b) << i;
  }
  std::set<std::uint16_t> ops;
  for (const Word& w : lists[1]) ops.insert(w.opcode());
  for (Op op : {Op::JumpSpeed, Op::QSwitchPeriod, Op::MarkCurrent, Op::MarkSpeed, Op::LaserOnDelay,
                Op::LaserOffDelay, Op::PolygonDelay, Op::JumpDelay})
    EXPECT_TRUE(ops.count(std::uint16_t(op))) << command_name(std::uint16_t(op));
}

}  // namespace
}  // namespace mark::lmc

namespace mark::lmc {
namespace {

// A list that failed mid-packet (the sink threw) leaves nothing behind for the next list.
TEST(LmcEncoder, AFailedListLeavesNothingForTheNext) {
  const FieldUnits units(110);
  bool fail = true;
  std::vector<std::vector<Word>> sent;
  JobEncoder enc(units, [&](const ListPacket& p, const PacketInfo&) {
    if (fail) throw std::runtime_error("stall");
    std::vector<Word> words;
    for (std::size_t i = 0; i < kCommandsPerPacket; ++i) words.push_back(load(p.bytes().data() + 12 * i));
    sent.push_back(words);
  });
  const BoardPen bp = encode_pen(test::golden_pen(), 0, units);
  enc.start_list(0.008, 1);
  enc.apply_pen(bp);
  EXPECT_THROW(
      for (int i = 0; i < 300; ++i) enc.add(DeviceCommand::mark_to(1 + 0.01 * i, 0), std::uint64_t(i)),
      std::runtime_error);
  fail = false;
  enc.start_list(0, 1);
  enc.apply_pen(bp);
  enc.finish(0);
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_EQ(sent[0][0], word(Op::ReadyMark));
  for (const Word& w : sent[0]) EXPECT_NE(w.opcode(), static_cast<std::uint16_t>(Op::MarkTo));
}

}  // namespace
}  // namespace mark::lmc
