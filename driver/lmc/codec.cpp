#include "driver/lmc/codec.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace mark::lmc {
namespace {

// Opcode → table entry, for the two documented ranges (0x00..0xFF single, 0x8000..0x80FF list).
struct Index {
  std::array<const CommandSpec*, 256> single{};
  std::array<const CommandSpec*, 256> list{};
  Index() {
    for (const CommandSpec& s : kCommands) {
      const auto op = static_cast<std::uint16_t>(s.op);
      (is_list(op) ? list : single)[op & 0xFF] = &s;
    }
  }
};
const Index& index() {
  static const Index i;
  return i;
}

std::string fmt(const char* f, double a, double b = 0, double c = 0) {
  char buf[240];
  std::snprintf(buf, sizeof buf, f, a, b, c);
  return buf;
}

[[noreturn]] void refuse(std::string_view what, const std::string& detail) {
  throw EncodeError("lmc: " + std::string(what) + " " + detail);
}

std::uint16_t rounded(double v, double lo, double hi, std::string_view what, const char* unit,
                      double shown) {
  const double r = std::round(v);
  if (!std::isfinite(v) || r < lo || r > hi) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "%g does not fit the board's word: %g %s, allowed %g .. %g",
                  shown, r, unit, lo, hi);
    refuse(what, buf);
  }
  return static_cast<std::uint16_t>(r);
}

}  // namespace

const CommandSpec* find_command(std::uint16_t opcode) {
  if ((opcode & 0x7F00) != 0) return nullptr;
  return (is_list(opcode) ? index().list : index().single)[opcode & 0xFF];
}

std::string_view command_name(std::uint16_t opcode) {
  if (const CommandSpec* s = find_command(opcode)) return s->name;
  return is_list(opcode) ? "unknown list command" : "unknown single command";
}

// --------------------------------------------------------------------------------------------
// Field units

FieldUnits::FieldUnits(double field_mm, AxisMap axes, PolygonDelayUnit polygon)
    : field_mm_(field_mm),
      per_mm_(65535.0 / field_mm),
      scale_x_(axes.flip_x ? -per_mm_ : per_mm_),
      scale_y_(axes.flip_y ? -per_mm_ : per_mm_),
      speed_factor_(per_mm_ / 1000.0),
      edge_(field_mm / 2 * (1 + 1e-12)),
      axes_(axes),
      polygon_(polygon) {
  if (!(field_mm > 0) || !std::isfinite(field_mm) || field_mm > 10000)
    throw EncodeError(fmt("lmc: lens field %g mm is not a size (allowed 0 < field ≤ 10000 mm)",
                          field_mm));
}

void FieldUnits::refuse_point(double x_mm, double y_mm) const {
  refuse("point", fmt("(%.4f, %.4f) mm lies outside the %g mm field", x_mm, y_mm, field_mm_));
}

std::array<double, 2> FieldUnits::field_point(std::uint16_t p1, std::uint16_t p2) const {
  double a = (double(p1) - 32768.0) / per_mm_;
  double b = (double(p2) - 32768.0) / per_mm_;
  if (axes_.swap_xy) std::swap(a, b);
  if (axes_.flip_x) a = -a;
  if (axes_.flip_y) b = -b;
  return {a, b};
}

// --------------------------------------------------------------------------------------------
// Unit encoders

void refuse_speed(double mm_s, const FieldUnits& u, std::string_view what) {
  const double lo = 1000.0 / u.units_per_mm(), hi = 65535.0 * 1000.0 / u.units_per_mm();
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "%g mm/s is outside what the board runs on a %g mm lens (allowed %.3f .. %.0f mm/s)",
                mm_s, u.field_mm(), lo, hi);
  refuse(what, buf);
}

std::uint16_t timed_speed_word(double length, double ticks, const FieldUnits& u, std::string_view what) {
  const double word = std::ceil(100.0 * length / ticks);
  if (!(word < 65536.0)) refuse_speed(length / (ticks * kTick_s) / u.units_per_mm(), u, what);
  return static_cast<std::uint16_t>(std::max(1.0, word));
}

std::array<std::uint16_t, 2> encode_signed_us(double seconds, std::string_view what) {
  const double us = std::round(seconds * 1e6);
  if (!std::isfinite(seconds) || std::abs(us) > 65535)
    refuse(what, fmt("%g µs does not fit (allowed -65535 .. 65535 µs)", seconds * 1e6));
  return {static_cast<std::uint16_t>(std::abs(us)), static_cast<std::uint16_t>(us < 0 ? 0x8000 : 0)};
}

std::uint16_t encode_time_10us(double seconds, std::uint32_t max, std::string_view what) {
  const double t = std::round(seconds * 1e5);
  if (!std::isfinite(seconds) || t < 0 || t > max)
    refuse(what, fmt("%g µs does not fit (allowed 0 .. %g µs in 10 µs steps)", seconds * 1e6,
                     double(max) * 10));
  return static_cast<std::uint16_t>(t);
}

std::array<std::uint16_t, 2> encode_polygon_delay(double seconds, PolygonDelayUnit unit) {
  if (unit == PolygonDelayUnit::signed_us) return encode_signed_us(seconds, "polygon delay");
  return {encode_time_10us(seconds, 0xFFFF, "polygon delay"), 0};
}

std::uint16_t encode_period_50ns(double khz) {
  if (!(khz > 0) || !std::isfinite(khz))
    refuse("Q-switch frequency", fmt("%g kHz is not a frequency (allowed 0.306 .. 20000 kHz)", khz));
  return rounded(20000.0 / khz, 1, 65535, "Q-switch frequency", "50 ns periods", khz);
}

std::uint16_t encode_period_100ns(double khz) {
  if (!(khz > 0) || !std::isfinite(khz))
    refuse("mark frequency", fmt("%g kHz is not a frequency (allowed 0.153 .. 10000 kHz)", khz));
  return rounded(10000.0 / khz, 1, 65535, "mark frequency", "100 ns periods", khz);
}

std::uint16_t encode_power_12bit(double pct) {
  if (!(pct >= 0 && pct <= 100))
    refuse("power", fmt("%g %% is outside 0 .. 100 %%", pct));
  return static_cast<std::uint16_t>(std::round(pct * 4095.0 / 100.0));
}

std::uint16_t encode_co2_fpk(double khz) {
  if (!(khz > 0) || !std::isfinite(khz))
    refuse("first-pulse killer", fmt("%g kHz is not a frequency", khz));
  return rounded(2000.0 / khz, 1, 65535, "first-pulse killer", "words (2000 / kHz)", khz);
}

std::uint16_t encode_power_ratio(double pct, double khz) {
  if (!(pct >= 0 && pct <= 100)) refuse("power", fmt("%g %% is outside 0 .. 100 %%", pct));
  if (!(khz > 0) || !std::isfinite(khz)) refuse("power ratio", fmt("%g kHz is not a frequency", khz));
  return rounded(200.0 * pct / khz, 0, 65535, "power ratio", "50 ns (200 × % / kHz)", pct);
}

std::uint16_t encode_pulse_width_ns(double ns) {
  return rounded(ns, 1, 65535, "MOPA pulse width", "ns", ns);
}

std::uint16_t encode_cor_delta(std::int64_t delta) {
  if (delta <= -0x8000 || delta >= 0x8000)
    refuse("correction delta", fmt("%g units does not fit the sign-magnitude word "
                                   "(allowed -32767 .. 32767)", double(delta)));
  return static_cast<std::uint16_t>(delta >= 0 ? delta : -delta + 0x8000);
}

std::int32_t decode_cor_delta(std::uint16_t w) {
  return (w & 0x8000) ? -std::int32_t(w & 0x7FFF) : std::int32_t(w);
}

double decode_speed(std::uint16_t word, const FieldUnits& u) {
  return double(word) * 1000.0 / u.units_per_mm();
}

double decode_signed_us(std::uint16_t magnitude, std::uint16_t sign) {
  return (sign & 0x8000 ? -1.0 : 1.0) * double(magnitude) * 1e-6;
}

double decode_polygon_delay(std::uint16_t p1, std::uint16_t p2, PolygonDelayUnit unit) {
  return unit == PolygonDelayUnit::signed_us ? decode_signed_us(p1, p2) : double(p1) * 1e-5;
}

// --------------------------------------------------------------------------------------------
// The table-driven encoder and decoder

namespace {
bool two_words(Unit unit, const FieldUnits& u) {
  return unit == Unit::signed_us ||
         (unit == Unit::polygon_delay && u.polygon_unit() == PolygonDelayUnit::signed_us);
}
}  // namespace

Word encode(Op op, std::initializer_list<double> values, const FieldUnits& u) {
  const CommandSpec& s = spec_of(op);
  if (values.size() != s.count)
    throw EncodeError("lmc: " + std::string(s.name) + " takes " + std::to_string(s.count) +
                      " parameters, not " + std::to_string(values.size()));
  Word c;
  c.w[0] = static_cast<std::uint16_t>(op);
  const double* v = values.begin();
  std::size_t k = 1;
  for (std::size_t i = 0; i < s.count; ++i) {
    const ParamSpec& p = s.params[i];
    const std::string what = std::string(s.name) + " " + std::string(p.name);
    switch (p.unit) {
      case Unit::x: {
        // x and y are encoded together: the axis map may swap them.
        const auto xy = u.point(v[i], v[i + 1]);
        c.w[k++] = xy[0];
        c.w[k++] = xy[1];
        ++i;
        break;
      }
      case Unit::y: refuse(what, "comes without its x");
      case Unit::speed: c.w[k++] = encode_speed(v[i], u, what); break;
      case Unit::signed_us: {
        const auto d = encode_signed_us(v[i], what);
        c.w[k++] = d[0];
        c.w[k++] = d[1];
        break;
      }
      case Unit::polygon_delay: {
        const auto d = encode_polygon_delay(v[i], u.polygon_unit());
        c.w[k++] = d[0];
        if (two_words(p.unit, u)) c.w[k++] = d[1];
        break;
      }
      case Unit::time_10us: c.w[k++] = encode_time_10us(v[i], 0xFFFF, what); break;
      case Unit::dwell_10us: c.w[k++] = encode_time_10us(v[i], 60000, what); break;
      case Unit::period_50ns: c.w[k++] = encode_period_50ns(v[i]); break;
      case Unit::period_100ns: c.w[k++] = encode_period_100ns(v[i]); break;
      case Unit::power_12bit: c.w[k++] = encode_power_12bit(v[i]); break;
      case Unit::pulse_width_ns: c.w[k++] = encode_pulse_width_ns(v[i]); break;
      case Unit::cor_delta: c.w[k++] = encode_cor_delta(std::llround(v[i])); break;
      case Unit::word:
      case Unit::distance:
      case Unit::port:
        c.w[k++] = rounded(v[i], 0, 65535, what, "word", v[i]);
        break;
    }
  }
  return c;
}

std::array<double, 5> decode_params(const Word& c, const CommandSpec& s, const FieldUnits& u) {
  std::array<double, 5> out{};
  std::size_t k = 1;
  for (std::size_t i = 0; i < s.count && k <= 5; ++i) {
    const Unit unit = s.params[i].unit;
    const std::uint16_t a = c.w[k], b = k < 5 ? c.w[k + 1] : 0;
    switch (unit) {
      case Unit::x: {
        const auto p = u.field_point(a, b);
        out[i] = p[0];
        if (i + 1 < 5) out[i + 1] = p[1];
        ++i;
        k += 2;
        continue;
      }
      case Unit::speed: out[i] = decode_speed(a, u); break;
      case Unit::signed_us: out[i] = decode_signed_us(a, b); break;
      case Unit::polygon_delay: out[i] = decode_polygon_delay(a, b, u.polygon_unit()); break;
      case Unit::time_10us:
      case Unit::dwell_10us: out[i] = double(a) * 1e-5; break;
      case Unit::period_50ns: out[i] = a ? 20000.0 / a : 0; break;
      case Unit::period_100ns: out[i] = a ? 10000.0 / a : 0; break;
      case Unit::power_12bit: out[i] = double(a) * 100.0 / 4095.0; break;
      case Unit::cor_delta: out[i] = decode_cor_delta(a); break;
      default: out[i] = a; break;
    }
    k += two_words(unit, u) ? 2 : 1;
  }
  return out;
}

std::array<std::uint8_t, kCommandBytes> bytes(const Word& c) {
  std::array<std::uint8_t, kCommandBytes> b{};
  store(c, b.data());
  return b;
}

void ListPacket::pad() const {
  for (std::size_t i = used_; i < kCommandsPerPacket; ++i) {
    std::uint16_t* w = words_.data() + 6 * i;
    w[0] = wire(static_cast<std::uint16_t>(Op::EndOfList));
    w[1] = w[2] = w[3] = w[4] = w[5] = 0;
  }
}

std::string describe(const Word& c, const FieldUnits& u) {
  char buf[64];
  const CommandSpec* s = find_command(c.opcode());
  if (!s) {
    std::snprintf(buf, sizeof buf, "0x%04X (%s)", c.opcode(),
                  std::string(command_name(c.opcode())).c_str());
    std::string out = buf;
    for (int i = 1; i <= 5; ++i) {
      std::snprintf(buf, sizeof buf, " %04X", c.p(i));
      out += buf;
    }
    return out;
  }
  std::string out(s->name);
  const auto v = decode_params(c, *s, u);
  for (std::size_t i = 0; i < s->count; ++i) {
    const ParamSpec& p = s->params[i];
    const char* unit = "";
    double shown = v[i];
    switch (p.unit) {
      case Unit::x:
      case Unit::y: unit = " mm"; break;
      case Unit::speed: unit = " mm/s"; break;
      case Unit::signed_us:
      case Unit::time_10us:
      case Unit::dwell_10us:
      case Unit::polygon_delay: unit = " µs"; shown *= 1e6; break;
      case Unit::period_50ns:
      case Unit::period_100ns: unit = " kHz"; break;
      case Unit::power_12bit: unit = " %"; break;
      case Unit::pulse_width_ns: unit = " ns"; break;
      default: break;
    }
    std::snprintf(buf, sizeof buf, " %.*s=%.4g%s", int(p.name.size()), p.name.data(), shown, unit);
    out += buf;
  }
  return out;
}

// --------------------------------------------------------------------------------------------
// Replies

Reply decode_reply(std::span<const std::uint8_t> b) {
  if (b.size() != kReplyBytes)
    throw ReplyError("lmc: reply of " + std::to_string(b.size()) + " bytes, expected " +
                     std::to_string(kReplyBytes));
  Reply r;
  for (std::size_t i = 0; i < 4; ++i)
    r.w[i] = static_cast<std::uint16_t>(b[2 * i] | (b[2 * i + 1] << 8));
  return r;
}

std::array<std::uint8_t, kReplyBytes> encode_reply(const Reply& r) {
  std::array<std::uint8_t, kReplyBytes> b{};
  for (std::size_t i = 0; i < 4; ++i) {
    b[2 * i] = static_cast<std::uint8_t>(r.w[i] & 0xFF);
    b[2 * i + 1] = static_cast<std::uint8_t>(r.w[i] >> 8);
  }
  return b;
}

std::string serial_string(const Reply& r) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%04X%04X", r.w[1], r.w[2]);
  return buf;
}

std::optional<std::array<std::uint16_t, 2>> parse_serial(std::string_view text) {
  if (text.empty() || text.size() > 8) return std::nullopt;
  std::uint32_t v = 0;
  for (char ch : text) {
    int d;
    if (ch >= '0' && ch <= '9') d = ch - '0';
    else if (ch >= 'a' && ch <= 'f') d = ch - 'a' + 10;
    else if (ch >= 'A' && ch <= 'F') d = ch - 'A' + 10;
    else return std::nullopt;
    v = v << 4 | std::uint32_t(d);
  }
  return std::array<std::uint16_t, 2>{static_cast<std::uint16_t>(v >> 16),
                                      static_cast<std::uint16_t>(v & 0xFFFF)};
}

}  // namespace mark::lmc
