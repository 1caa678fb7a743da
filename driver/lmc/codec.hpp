#pragma once
// The BJJCZ "LMC" wire protocol in one place (galvo.md §1): every command the driver, the
// emulated board and the capture dump know is declared once in kCommands — opcode, name, whether
// the board answers it, and its parameters with their units — the way Klipper declares its wire
// commands with DECL_COMMAND. Everything else here is what the table needs: the unit encoders
// (mm → field units around 0x8000, mm/s → units per ms, µs delays with the sign flag, 10 µs
// times, Q-switch period in 50 ns, 12-bit power, sign-magnitude correction deltas), the 12-byte
// command word and the 3072-byte list packet, and reply decoding. The session logic (init, flow
// control, abort) lives in session.hpp, not here.
//
// A command word is six little-endian uint16 [opcode, p1..p5]. Opcodes ≥ 0x8000 are list
// commands, packed 256 to a packet and padded with EndOfList (0x8002); smaller ones are single
// (real-time) commands sent alone as 12 bytes, answered (except WriteCorLine) by an 8-byte reply
// of four little-endian uint16 whose last word is the status register.
//
// Rounding: coordinates, speeds and segment lengths are truncated, as meerk40t and galvoplotter
// do, so the same millimetres give the same bytes as those drivers (galvo.md §1.9's golden
// rectangle); the cost is at most one field unit (1.7 µm on a 110 mm lens) of offset. Times,
// power and periods are rounded to nearest, as they do too.
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "driver/device_error.hpp"

namespace mark::lmc {

// The board's clock: every delay and timed word counts ticks of 10 µs.
inline constexpr double kTick_s = 10e-6;

// ---------------------------------------------------------------------------------------------
// Opcodes (names as galvoplotter's consts.py, without the "list" prefix).
enum class Op : std::uint16_t {
  // list commands
  JumpTo = 0x8001,
  EndOfList = 0x8002,  // also the padding of every packet
  LaserOnPoint = 0x8003,
  DelayTime = 0x8004,
  MarkTo = 0x8005,
  JumpSpeed = 0x8006,
  LaserOnDelay = 0x8007,
  LaserOffDelay = 0x8008,
  MarkFreq = 0x800A,
  MarkPowerRatio = 0x800B,
  MarkSpeed = 0x800C,
  JumpDelay = 0x800D,
  PolygonDelay = 0x800F,
  ListWritePort = 0x8011,
  MarkCurrent = 0x8012,
  FlyEnable = 0x801A,
  QSwitchPeriod = 0x801B,
  FlyDelay = 0x801D,
  SetCo2Fpk = 0x801E,
  FiberOpenMO = 0x8021,
  WaitForInput = 0x8022,
  FiberYLPMPulseWidth = 0x8026,
  ReadyMark = 0x8051,
  // single (real-time) commands
  DisableLaser = 0x0002,
  EnableLaser = 0x0004,
  ExecuteList = 0x0005,
  SetPwmPulseWidth = 0x0006,
  GetVersion = 0x0007,
  GetSerialNo = 0x0009,
  GetListStatus = 0x000A,
  GetPositionXY = 0x000C,
  GotoXY = 0x000D,
  LaserSignalOff = 0x000E,
  LaserSignalOn = 0x000F,
  WriteCorLine = 0x0010,
  ResetList = 0x0012,
  RestartList = 0x0013,
  WriteCorTable = 0x0015,
  SetControlMode = 0x0016,
  SetDelayMode = 0x0017,
  SetMaxPolyDelay = 0x0018,
  SetEndOfList = 0x0019,
  SetFirstPulseKiller = 0x001A,
  SetLaserMode = 0x001B,
  SetTiming = 0x001C,
  SetStandby = 0x001D,
  SetPwmHalfPeriod = 0x001E,
  StopExecute = 0x001F,
  StopList = 0x0020,
  WritePort = 0x0021,
  WriteAnalogPort1 = 0x0022,
  WriteAnalogPort2 = 0x0023,
  ReadPort = 0x0025,
  GetMarkCount = 0x002D,
  SetFpkParam2 = 0x002E,
  SetFlyRes = 0x0032,
  FiberSetMo = 0x0033,
  FiberGetStMoAp = 0x0034,
  DisableZ = 0x0039,
  EnableZ = 0x003A,
  Reset = 0x0040,
  GetMarkTime = 0x0041,
};

constexpr bool is_list(std::uint16_t opcode) { return opcode >= 0x8000; }
constexpr bool is_list(Op op) { return is_list(static_cast<std::uint16_t>(op)); }

// ---------------------------------------------------------------------------------------------
// Parameter units. Each has one encoder (physical value → word(s)) and one decoder (word(s) →
// physical value); a unit marked two-word fills its word and the next (magnitude, sign flag).
enum class Unit : std::uint8_t {
  word,           // a raw 16-bit value (modes, counts, flags)
  x,              // field coordinate, mm → 0..0xFFFF around 0x8000 (axis mapping applied)
  y,
  distance,       // segment length in field units (truncated, clamped to 0xFFFF)
  speed,          // mm/s → field units per ms (truncated), 1..0xFFFF
  signed_us,      // s → |µs| in this word, 0x8000 in the next if negative (two words)
  time_10us,      // s → 10 µs units, 0..0xFFFF
  dwell_10us,     // s → 10 µs units, 0..60000 (LaserOnPoint's documented limit)
  polygon_delay,  // s → 10 µs units, or µs + sign flag: PolygonDelayUnit (two words)
  period_50ns,    // kHz → Q-switch period in 50 ns units = 20000 / f
  period_100ns,   // kHz → CO2/UV period in 100 ns units = 10000 / f
  power_12bit,    // % → 0..0xFFF
  port,           // 16 output bits
  pulse_width_ns, // MOPA pulse width, ns (1..0xFFFF)
  cor_delta,      // correction delta, sign-magnitude 16-bit (pre-encoded word)
};

struct ParamSpec {
  std::string_view name;
  Unit unit = Unit::word;
};

struct CommandSpec {
  Op op;
  std::string_view name;
  bool reply;  // single commands: the board answers with 8 bytes
  std::uint8_t count = 0;  // parameters in use
  std::array<ParamSpec, 5> params{};
};

namespace detail {
constexpr CommandSpec cmd(Op op, std::string_view name, bool reply,
                          std::initializer_list<ParamSpec> ps = {}) {
  CommandSpec s{op, name, reply, 0, {}};
  for (const ParamSpec& p : ps) s.params[s.count++] = p;
  return s;
}
constexpr ParamSpec w(std::string_view n) { return {n, Unit::word}; }
}  // namespace detail

// THE table. Parameter lists follow galvo.md §1.4–§1.6; a two-word unit takes one entry (the
// sign flag word is implied). Unknown semantics are kept as raw words.
inline constexpr CommandSpec kCommands[] = {
    // list commands
    detail::cmd(Op::JumpTo, "JumpTo", false, {{"x", Unit::x}, {"y", Unit::y}, detail::w("angle"), {"distance", Unit::distance}}),
    detail::cmd(Op::EndOfList, "EndOfList", false),
    detail::cmd(Op::LaserOnPoint, "LaserOnPoint", false, {{"dwell", Unit::dwell_10us}}),
    detail::cmd(Op::DelayTime, "DelayTime", false, {{"time", Unit::time_10us}}),
    detail::cmd(Op::MarkTo, "MarkTo", false, {{"x", Unit::x}, {"y", Unit::y}, detail::w("angle"), {"distance", Unit::distance}}),
    detail::cmd(Op::JumpSpeed, "JumpSpeed", false, {{"speed", Unit::speed}}),
    detail::cmd(Op::LaserOnDelay, "LaserOnDelay", false, {{"delay", Unit::signed_us}}),
    detail::cmd(Op::LaserOffDelay, "LaserOffDelay", false, {{"delay", Unit::signed_us}}),
    detail::cmd(Op::MarkFreq, "MarkFreq", false, {{"period", Unit::period_100ns}}),
    detail::cmd(Op::MarkPowerRatio, "MarkPowerRatio", false, {detail::w("ratio")}),
    detail::cmd(Op::MarkSpeed, "MarkSpeed", false, {{"speed", Unit::speed}}),
    detail::cmd(Op::JumpDelay, "JumpDelay", false, {{"delay", Unit::signed_us}}),
    detail::cmd(Op::PolygonDelay, "PolygonDelay", false, {{"delay", Unit::polygon_delay}}),
    detail::cmd(Op::ListWritePort, "WritePort(list)", false, {{"port", Unit::port}}),
    detail::cmd(Op::MarkCurrent, "MarkCurrent", false, {{"power", Unit::power_12bit}}),
    detail::cmd(Op::FlyEnable, "FlyEnable", false, {detail::w("enable")}),
    detail::cmd(Op::QSwitchPeriod, "QSwitchPeriod", false, {{"period", Unit::period_50ns}}),
    detail::cmd(Op::FlyDelay, "FlyDelay", false, {{"delay", Unit::signed_us}}),
    detail::cmd(Op::SetCo2Fpk, "SetCo2FPK", false, {detail::w("fpk1"), detail::w("fpk2")}),
    detail::cmd(Op::FiberOpenMO, "FiberOpenMO", false, {detail::w("open")}),
    detail::cmd(Op::WaitForInput, "WaitForInput", false, {detail::w("mask"), detail::w("level")}),
    detail::cmd(Op::FiberYLPMPulseWidth, "FiberYLPMPulseWidth", false, {{"width", Unit::pulse_width_ns}}),
    detail::cmd(Op::ReadyMark, "ReadyMark", false),
    // single commands
    detail::cmd(Op::DisableLaser, "DisableLaser", true),
    detail::cmd(Op::EnableLaser, "EnableLaser", true),
    detail::cmd(Op::ExecuteList, "ExecuteList", true),
    detail::cmd(Op::SetPwmPulseWidth, "SetPwmPulseWidth", true, {detail::w("width")}),
    detail::cmd(Op::GetVersion, "GetVersion", true),
    detail::cmd(Op::GetSerialNo, "GetSerialNo", true),
    detail::cmd(Op::GetListStatus, "GetListStatus", true),
    detail::cmd(Op::GetPositionXY, "GetPositionXY", true),
    detail::cmd(Op::GotoXY, "GotoXY", true, {{"x", Unit::x}, {"y", Unit::y}, detail::w("angle"), {"distance", Unit::distance}}),
    detail::cmd(Op::LaserSignalOff, "LaserSignalOff", true),
    detail::cmd(Op::LaserSignalOn, "LaserSignalOn", true),
    detail::cmd(Op::WriteCorLine, "WriteCorLine", false, {{"dx", Unit::cor_delta}, {"dy", Unit::cor_delta}, detail::w("non_first")}),
    detail::cmd(Op::ResetList, "ResetList", true),
    detail::cmd(Op::RestartList, "RestartList", true),
    detail::cmd(Op::WriteCorTable, "WriteCorTable", true, {detail::w("table")}),
    detail::cmd(Op::SetControlMode, "SetControlMode", true, {detail::w("mode")}),
    detail::cmd(Op::SetDelayMode, "SetDelayMode", true, {detail::w("mode")}),
    detail::cmd(Op::SetMaxPolyDelay, "SetMaxPolyDelay", true, {{"delay", Unit::signed_us}}),
    detail::cmd(Op::SetEndOfList, "SetEndOfList", true, {detail::w("end")}),
    detail::cmd(Op::SetFirstPulseKiller, "SetFirstPulseKiller", true, {detail::w("fpk")}),
    detail::cmd(Op::SetLaserMode, "SetLaserMode", true, {detail::w("mode")}),
    detail::cmd(Op::SetTiming, "SetTiming", true, {detail::w("timing")}),
    detail::cmd(Op::SetStandby, "SetStandby", true, {detail::w("standby1"), detail::w("standby2")}),
    detail::cmd(Op::SetPwmHalfPeriod, "SetPwmHalfPeriod", true, {detail::w("half_period")}),
    detail::cmd(Op::StopExecute, "StopExecute", true),
    detail::cmd(Op::StopList, "StopList", true),
    detail::cmd(Op::WritePort, "WritePort", true, {{"port", Unit::port}}),
    detail::cmd(Op::WriteAnalogPort1, "WriteAnalogPort1", true, {detail::w("value")}),
    detail::cmd(Op::WriteAnalogPort2, "WriteAnalogPort2", true, {detail::w("value")}),
    detail::cmd(Op::ReadPort, "ReadPort", true),
    detail::cmd(Op::GetMarkCount, "GetMarkCount", true),
    detail::cmd(Op::SetFpkParam2, "SetFpkParam2", true, {detail::w("max_voltage"), detail::w("min_voltage"), detail::w("t1"), detail::w("t2")}),
    detail::cmd(Op::SetFlyRes, "SetFlyRes", true, {detail::w("res1"), detail::w("res2"), detail::w("res3"), detail::w("res4")}),
    detail::cmd(Op::FiberSetMo, "Fiber_SetMo", true, {detail::w("open")}),
    detail::cmd(Op::FiberGetStMoAp, "Fiber_GetStMO_AP", true),
    detail::cmd(Op::DisableZ, "DisableZ", true),
    detail::cmd(Op::EnableZ, "EnableZ", true),
    detail::cmd(Op::Reset, "Reset", true),
    detail::cmd(Op::GetMarkTime, "GetMarkTime", true, {detail::w("mode")}),
};

// The table entry of an opcode, or nullptr for an opcode nobody has documented.
const CommandSpec* find_command(std::uint16_t opcode);
constexpr const CommandSpec& spec_of(Op op) {
  for (const CommandSpec& s : kCommands)
    if (s.op == op) return s;
  throw "opcode missing from kCommands";  // compile-time error when used in a constant expression
}
std::string_view command_name(std::uint16_t opcode);  // "0x1234?" style for unknown opcodes

// ---------------------------------------------------------------------------------------------
// Units

// Encoding refused: a value outside what its parameter can carry. The message names the
// command, the parameter, the value and the allowed range.
class EncodeError : public DeviceError {
 public:
  using DeviceError::DeviceError;
};

// The references disagree (galvo.md §1.4): two of three send µs (galvoplotter with the sign flag,
// balor as a plain word), meerk40t since 2025-08 sends µs / 10. LmcOptions defaults to the
// majority; `marker lmc probe` measures what a board takes.
enum class PolygonDelayUnit {
  ten_us,     // µs / 10, no sign (meerk40t since 2025-08, commit 3616dfe5d; its test vector)
  signed_us   // µs with the sign flag (galvoplotter, balor, meerk40t before 2025-08)
};

// How the field frame (x right, y up, as the layout has it) maps onto the board's two
// coordinate words: p1 = x, p2 = y, each mirrored when flipped, then swapped. AxisMap{} is that
// plain mapping; kEzCadAxes is what EzCad does on a default machine.
struct AxisMap {
  bool swap_xy = false;
  bool flip_x = false;
  bool flip_y = false;
  bool operator==(const AxisMap&) const = default;
};
// EzCad's default: the first word is y, the second x, neither mirrored. Balor labels MarkTo's
// words (y, x) from EzCad captures on an LMCV4-FIBER-M (balor/command_list.py, OpCut / OpTravel),
// and meerk40t's galvo device defaults to swap_xy + flip_y on its y-down scene since 09d37c2
// (2022), which is the same map (its test vector: scene (20, 20) mm on a 110 mm lens → words
// D174 2E8B). The same settings in meerk40t's terms: swap_xy = ours, flip_x = ours,
// flip_y = not ours (its scene's y points down). docs/lmc.md, "Axes".
inline constexpr AxisMap kEzCadAxes{true, false, false};

// Everything a unit encoder needs besides the value.
class FieldUnits {
 public:
  explicit FieldUnits(double field_mm = 110, AxisMap axes = {},
                      PolygonDelayUnit polygon = PolygonDelayUnit::ten_us);

  double field_mm() const { return field_mm_; }
  double half_field_mm() const { return field_mm_ / 2; }
  double units_per_mm() const { return per_mm_; }
  const AxisMap& axes() const { return axes_; }
  PolygonDelayUnit polygon_unit() const { return polygon_; }

  // Field point (mm) → board words (p1, p2). Callers check the field first: a point outside
  // |x|, |y| ≤ field/2 throws EncodeError here as a last line of defence. Inline: the list
  // encoder calls it for every move.
  std::array<std::uint16_t, 2> point(double x_mm, double y_mm) const {
    if (!in_field(x_mm, y_mm)) refuse_point(x_mm, y_mm);
    // The mirroring is in the signs of the scales: (−x)·k and x·(−k) are the same double.
    double a = x_mm * scale_x_, b = y_mm * scale_y_;
    if (axes_.swap_xy) std::swap(a, b);
    return {unit(a), unit(b)};
  }
  // Board words → field point (mm), the inverse up to the truncation.
  std::array<double, 2> field_point(std::uint16_t p1, std::uint16_t p2) const;
  bool in_field(double x_mm, double y_mm) const {
    // |x| ≤ h, written so that a NaN fails too.
    return std::abs(x_mm) <= edge_ && std::abs(y_mm) <= edge_;
  }
  double speed_factor() const { return speed_factor_; }  // mm/s → units per ms

 private:
  // A coordinate already in units from the centre → its word. Truncation, as the reference
  // drivers (see the top of this file). In the field u ≥ 0.4999
  // (−half field maps to 0.5), so truncating is flooring; the min only absorbs in_field's 1e-12
  // tolerance at the +edge.
  std::uint16_t unit(double scaled) const {
    const double u = 32768.0 + scaled;
    return static_cast<std::uint16_t>(u < 65535.0 ? u : 65535.0);
  }
  [[noreturn]] void refuse_point(double x_mm, double y_mm) const;

  double field_mm_;
  double per_mm_;
  double scale_x_, scale_y_;  // ±per_mm_: the field's x and y in units, mirrored where flipped
  double speed_factor_;  // per_mm_ / 1000, kept: the list encoder needs it for every speed word
  double edge_;  // half the field, with a 1e-12 relative tolerance
  AxisMap axes_;
  PolygonDelayUnit polygon_;
};

// The encoders, one per unit (the table's parameters name which). Each throws EncodeError
// naming `what` when the value does not fit.
[[noreturn]] void refuse_speed(double mm_s, const FieldUnits& u, std::string_view what);
inline std::uint16_t encode_speed(double mm_s, const FieldUnits& u, std::string_view what = "speed") {
  const double units_per_ms = mm_s * u.speed_factor();
  // Written so that a NaN fails too.
  if (!(units_per_ms >= 1.0 && units_per_ms < 65536.0)) refuse_speed(mm_s, u, what);
  return static_cast<std::uint16_t>(units_per_ms);  // truncated, as meerk40t
}
// The speed word for a timed move (device_command.hpp): `length` units in `ticks` ticks. The
// board takes ⌈length / (word / 100)⌉ ticks (list_executor.hpp), so this is the smallest word
// whose move is no longer than `ticks`: exactly `ticks` when length ≥ ticks·(ticks − 1) / 100
// units, otherwise a word's step (1/100 unit per tick) is too coarse and the move is up to one
// word's share shorter. At least 1 (a slow crawl takes longer); EncodeError naming `what`
// above 0xFFFF.
std::uint16_t timed_speed_word(double length, double ticks, const FieldUnits& u, std::string_view what);
std::array<std::uint16_t, 2> encode_signed_us(double seconds, std::string_view what = "delay");
std::uint16_t encode_time_10us(double seconds, std::uint32_t max = 0xFFFF,
                               std::string_view what = "time");
std::array<std::uint16_t, 2> encode_polygon_delay(double seconds, PolygonDelayUnit unit);
std::uint16_t encode_period_50ns(double khz);
std::uint16_t encode_period_100ns(double khz);
std::uint16_t encode_power_12bit(double pct);
// CO2 / UV (meerk40t balormk/controller.py, fpk and power): the first-pulse killer as 2000 / f_kHz
// (SetCo2FPK, both words) and the power as the PWM's high time in 50 ns, 200 · P% / f_kHz
// (MarkPowerRatio: P% of the MarkFreq period of 10000 / f_kHz × 100 ns).
std::uint16_t encode_co2_fpk(double khz);
std::uint16_t encode_power_ratio(double pct, double khz);
std::uint16_t encode_pulse_width_ns(double ns);
// A correction delta in board units → sign-magnitude word; |delta| must be < 0x8000.
std::uint16_t encode_cor_delta(std::int64_t delta);
std::int32_t decode_cor_delta(std::uint16_t word);
// Segment length in field units between two encoded points: truncated, clamped to 0xFFFF.
inline double segment_length(std::array<std::uint16_t, 2> a, std::array<std::uint16_t, 2> b) {
  const std::int64_t dx = std::int64_t(a[0]) - b[0], dy = std::int64_t(a[1]) - b[1];
  return std::sqrt(double(dx * dx + dy * dy));  // exact below 2^53: one rounding, in the sqrt
}
// A segment length → its distance word: truncated, clamped to 0xFFFF.
inline std::uint16_t distance_word(double length) {
  return length >= 65535.0 ? std::uint16_t(0xFFFF) : static_cast<std::uint16_t>(length);
}
inline std::uint16_t segment_distance(std::array<std::uint16_t, 2> a,
                                      std::array<std::uint16_t, 2> b) {
  return distance_word(segment_length(a, b));
}
// The decoders: speed word → mm/s, signed µs pair → s, 10 µs word → s, period → kHz, 12-bit → %.
double decode_speed(std::uint16_t word, const FieldUnits& u);
double decode_signed_us(std::uint16_t magnitude, std::uint16_t sign);
double decode_polygon_delay(std::uint16_t p1, std::uint16_t p2, PolygonDelayUnit unit);

// ---------------------------------------------------------------------------------------------
// Command words and packets

inline constexpr std::size_t kCommandBytes = 12;
inline constexpr std::size_t kCommandsPerPacket = 256;
inline constexpr std::size_t kPacketBytes = kCommandBytes * kCommandsPerPacket;  // 0xC00
inline constexpr std::size_t kReplyBytes = 8;

struct Word {
  std::array<std::uint16_t, 6> w{};  // opcode, p1..p5
  std::uint16_t opcode() const { return w[0]; }
  std::uint16_t p(int i) const { return w[std::size_t(i)]; }  // i = 1..5
  bool operator==(const Word&) const = default;
};

constexpr Word word(Op op, std::uint16_t p1 = 0, std::uint16_t p2 = 0, std::uint16_t p3 = 0,
                    std::uint16_t p4 = 0, std::uint16_t p5 = 0) {
  return Word{{static_cast<std::uint16_t>(op), p1, p2, p3, p4, p5}};
}

inline void store(const Word& c, std::uint8_t* out) {
  if constexpr (std::endian::native == std::endian::little) {
    std::memcpy(out, c.w.data(), kCommandBytes);  // the wire is little-endian too
    return;
  }
  for (int i = 0; i < 6; ++i) {
    out[2 * i] = static_cast<std::uint8_t>(c.w[std::size_t(i)] & 0xFF);
    out[2 * i + 1] = static_cast<std::uint8_t>(c.w[std::size_t(i)] >> 8);
  }
}
inline Word load(const std::uint8_t* in) {
  Word c;
  if constexpr (std::endian::native == std::endian::little) {
    std::memcpy(c.w.data(), in, kCommandBytes);
    return c;
  }
  for (int i = 0; i < 6; ++i)
    c.w[std::size_t(i)] = static_cast<std::uint16_t>(in[2 * i] | (in[2 * i + 1] << 8));
  return c;
}
std::array<std::uint8_t, kCommandBytes> bytes(const Word& c);

// The table-driven encoder: physical values in the table's parameter order and units (mm, mm/s,
// s, kHz, %, ns; raw words and distances as numbers), e.g. encode(Op::SetStandby, {2000, 20}).
// Throws EncodeError for an unknown arity or a value its unit cannot carry. The list hot path
// (job_encoder.cpp) calls the same unit encoders directly, checked against this table at
// compile time.
Word encode(Op op, std::initializer_list<double> values, const FieldUnits& u);
// The inverse: each parameter of the table decoded to its physical value (same units).
std::array<double, 5> decode_params(const Word& c, const CommandSpec& spec, const FieldUnits& u);

// One list packet being filled: 256 slots, unused ones EndOfList. Held as 16-bit words in wire
// (little-endian) order: stores into it then cannot alias the encoder's own state the way byte
// stores would (a char store may alias anything, so the compiler would reload every member
// after each one); bytes() views the same memory as the 3072 bytes that go on the wire.
class ListPacket {
 public:
  ListPacket() = default;
  // Empties the packet. The words are not rewritten here: a packet that fills up overwrites
  // all 256, and bytes() pads what a short one leaves (re-padding every packet was 2 % of the
  // list encoder's time).
  void clear() { used_ = 0; }
  bool full() const { return used_ == kCommandsPerPacket; }
  bool empty() const { return used_ == 0; }
  std::size_t used() const { return used_; }
  void push(const Word& c) { push(c.w[0], c.w[1], c.w[2], c.w[3], c.w[4], c.w[5]); }
  void push(std::uint16_t op, std::uint16_t p1, std::uint16_t p2 = 0, std::uint16_t p3 = 0,
            std::uint16_t p4 = 0, std::uint16_t p5 = 0) {
    std::uint16_t* w = words_.data() + 6 * used_++;
    w[0] = wire(op), w[1] = wire(p1), w[2] = wire(p2), w[3] = wire(p3), w[4] = wire(p4), w[5] = wire(p5);
  }
  std::span<const std::uint8_t, kPacketBytes> bytes() const {
    if (used_ < kCommandsPerPacket) pad();
    return std::span<const std::uint8_t, kPacketBytes>(
        reinterpret_cast<const std::uint8_t*>(words_.data()), kPacketBytes);
  }

 private:
  static constexpr std::uint16_t wire(std::uint16_t v) {
    if constexpr (std::endian::native == std::endian::little) return v;
    return static_cast<std::uint16_t>(v << 8 | v >> 8);
  }
  // The slots from used_ on as EndOfList. Const: it only makes the words beyond used_ what
  // they mean; writes the same values every time.
  void pad() const;
  mutable std::array<std::uint16_t, kPacketBytes / 2> words_{};
  std::size_t used_ = 0;
};
static_assert(sizeof(std::array<std::uint16_t, kPacketBytes / 2>) == kPacketBytes);

// A human-readable line for one command word: "MarkTo x=12.500 mm y=-3.000 mm angle=0
// distance=5958" — the capture dump and test failure messages use it.
std::string describe(const Word& c, const FieldUnits& u);

// ---------------------------------------------------------------------------------------------
// Replies

namespace status {
inline constexpr std::uint16_t busy = 0x0004;    // a list is executing
inline constexpr std::uint16_t paused = 0x0008;  // GetListStatus: list paused (meerk40t)
inline constexpr std::uint16_t ready = 0x0020;   // another list packet may be sent
inline constexpr std::uint16_t axis = 0x0040;    // rotary axis moving
}  // namespace status

struct Reply {
  std::array<std::uint16_t, 4> w{};
  std::uint16_t status() const { return w[3]; }
  bool ready() const { return (w[3] & status::ready) != 0; }
  bool busy() const { return (w[3] & status::busy) != 0; }
  bool paused() const { return (w[3] & status::paused) != 0; }
};

class ReplyError : public DeviceError {
 public:
  using DeviceError::DeviceError;
};

// Exactly kReplyBytes bytes, or ReplyError naming the length.
Reply decode_reply(std::span<const std::uint8_t> bytes);
std::array<std::uint8_t, kReplyBytes> encode_reply(const Reply& r);
// GetSerialNo's data words (w1, w2) as 8 upper-case hex digits: the board serial `lmc:SERIAL`
// selects. (meerk40t prints all four words; w0 and the status word are not part of it here.)
std::string serial_string(const Reply& r);
// Parses "1A2B3C4D" (hex, up to 8 digits, case-insensitive) back into the two words.
std::optional<std::array<std::uint16_t, 2>> parse_serial(std::string_view text);

}  // namespace mark::lmc
