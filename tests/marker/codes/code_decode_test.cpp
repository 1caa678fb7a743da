// Codes marked on the simulated scanner and read back off the simulated part by libdmtx and
// ZBar: numeric, alphanumeric, GS1 (every AI of a UDI: 01, 11, 17, 10, 21), UTF-8 and control
// bytes; every Data Matrix size from 10×10 to 32×32 and the rectangular ones; square, dot and
// line modules on two heads; inverted and rotated codes. Each must decode to exactly the data
// meant. And marks that cannot read are reported as unreadable: dots too fast for the head's
// lag, lines too fast for the material.
#include <gtest/gtest.h>

#include "marker/codes/code_data.hpp"
#include "marker/job/head_pen.hpp"
#include "marker/job/simulate_plan.hpp"
#include "tests/marker/param_print.hpp"

namespace mark {
namespace {

struct Case {
  std::string name;
  Symbology symbology;
  std::string data;
  double module_mm = 0.25;
  ModuleStyle style = ModuleStyle::square;
  double speed_mm_s = 1000;
  HeadModel head = head_sl10();
  double angle_deg = 0;
  bool invert = false;
  int rows = 0, cols = 0;
  LaserSettings laser{};  // the default: Q-switched fiber at 30 kHz
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

struct Marked {
  PlacedCode code;
  CodeVerification verification;
};

// The code alone as a job, marked on the simulated head in device time and read back.
Marked run(const Case& c) {
  CodeObject code;
  code.spec.symbology = c.symbology;
  code.spec.data = c.data;
  code.spec.matrix_rows = c.rows;
  code.spec.matrix_cols = c.cols;
  code.layout.module_mm = c.module_mm;
  code.layout.style = c.style;
  code.layout.angle_deg = c.angle_deg;
  code.layout.invert = c.invert;
  code.layout.center = Point(3, -2);
  JobSpec spec;
  spec.codes.push_back(code);
  spec.head = c.head;
  spec.pen = pen_for_head(c.head, CornerStrategy::blanking, c.speed_mm_s);
  spec.laser = c.laser;
  SimulatedJob r = simulate_job(spec);
  return {r.job.codes.front(), r.codes.front()};
}

void expect_reads(const Case& c) {
  const Marked r = run(c);
  const CodeVerification& v = r.verification;
  EXPECT_TRUE(v.decoded) << c.name;
  std::string readers;
  for (const ReaderOutcome& o : v.readers)
    readers += " " + o.reader + (o.supported ? o.data_match ? " reads" : o.decoded ? " misreads" : " no read" : " n/a");
  EXPECT_TRUE(v.data_match) << c.name << ": read '" << printable_bytes(v.decoded_data) << "', meant '"
                            << printable_bytes(v.expected_data) << "';" << readers;
  EXPECT_EQ(v.modules_wrong, 0u) << c.name;
  EXPECT_GT(v.fill_ratio.value_or(0), 0.7) << c.name;
  EXPECT_LT(v.spill_ratio.value_or(1), 0.05) << c.name;
  // The reader's measured module is the intended one to within half a camera pixel and 4 %.
  ASSERT_TRUE(v.module_x_um.has_value()) << c.name;
  EXPECT_NEAR(*v.module_x_um, v.module_um, v.camera_px_um / 2 + 0.04 * v.module_um) << c.name;
  if (!is_linear(c.symbology)) {
    ASSERT_TRUE(v.axial_nonuniformity_pct.has_value());
    EXPECT_LT(*v.axial_nonuniformity_pct, 6.0) << c.name;  // grade A
  }
}

class DataStrings : public testing::TestWithParam<Case> {};
TEST_P(DataStrings, DecodeToTheSameBytes) { expect_reads(GetParam()); }

const std::string kUdi = "(01)09506000134352(11)250101(17)261231(10)LOT42(21)SN0001";

INSTANTIATE_TEST_SUITE_P(
    Codes, DataStrings,
    testing::Values(Case{"dm_numeric", Symbology::datamatrix, "2026000123456789"},
                    Case{"dm_alnum", Symbology::datamatrix, "SN 2026-000123 LOT A7"},
                    Case{"dm_utf8", Symbology::datamatrix, "Grüße aus Köln – 温度 ✓"},
                    Case{"dm_ansi_mh10", Symbology::datamatrix, "[)>\x1e" "06\x1dSSN0042\x1dVACME\x1e\x04"},
                    Case{"gs1_dm_udi", Symbology::gs1_datamatrix, kUdi},
                    Case{"gs1_dm_lot_last", Symbology::gs1_datamatrix, "(01)09506000134352(21)SN0001(10)LOT42"},
                    Case{"qr_numeric", Symbology::qr, "2026000123456789"},
                    Case{"qr_alnum", Symbology::qr, "SN 2026-000123 LOT A7"},
                    Case{"qr_utf8", Symbology::qr, "Grüße aus Köln – 温度 ✓"},
                    Case{"code128_alnum", Symbology::code128, "SN-2026-000123", 0.2},
                    Case{"code128_numeric", Symbology::code128, "0123456789012345", 0.2},
                    Case{"gs1_128_udi", Symbology::gs1_128, kUdi, 0.2}),
    [](const auto& info) { return info.param.name; });

class DataMatrixSizes : public testing::TestWithParam<MatrixSize> {};
TEST_P(DataMatrixSizes, DecodeAtEverySize) {
  const MatrixSize s = GetParam();
  Case c{std::to_string(s.rows) + "x" + std::to_string(s.cols), Symbology::datamatrix, "SN42", 0.2};
  c.rows = s.rows;
  c.cols = s.cols;
  expect_reads(c);
}
INSTANTIATE_TEST_SUITE_P(Codes, DataMatrixSizes,
                         testing::Values(MatrixSize{10, 10}, MatrixSize{12, 12}, MatrixSize{14, 14},
                                         MatrixSize{16, 16}, MatrixSize{18, 18}, MatrixSize{20, 20},
                                         MatrixSize{22, 22}, MatrixSize{24, 24}, MatrixSize{26, 26},
                                         MatrixSize{32, 32}, MatrixSize{8, 18}, MatrixSize{8, 32},
                                         MatrixSize{12, 26}, MatrixSize{12, 36}, MatrixSize{16, 36},
                                         MatrixSize{16, 48}),
                         [](const auto& info) {
                           return std::to_string(info.param.rows) + "x" + std::to_string(info.param.cols);
                         });

// Styles at settings where each is meant to be used: hatched squares at marking speed; dots slow
// enough that the head's lag does not shrink their circles (ZBar reads dotted QR only from
// 100 mm/s down: at 150 mm/s on SL14 it misses with every module right); lines at marking speed,
// from a beam radius inside each module row's edges at most the 0.035 mm hatch spacing apart:
// two 40 µm lines on a 0.06 mm module (the square style's smallest too), nine on the common
// 0.3 mm one (one line per module left both a striped grey that no reader decoded).
class StylesAndHeads : public testing::TestWithParam<Case> {};
TEST_P(StylesAndHeads, Decode) { expect_reads(GetParam()); }
std::vector<Case> style_cases() {
  std::vector<Case> out;
  for (const HeadModel& head : {head_sl10(), head_sl14()})
    for (Symbology s : {Symbology::datamatrix, Symbology::qr}) {
      const std::string base = head.name + "_" + std::string(s == Symbology::qr ? "qr" : "dm");
      out.push_back({base + "_square", s, "SN 2026-000123", 0.3, ModuleStyle::square, 1000, head});
      out.push_back({base + "_dot", s, "SN 2026-000123", 0.3, ModuleStyle::dot, 100, head});
      out.push_back({base + "_line", s, "SN 2026-000123", 0.06, ModuleStyle::line, 1000, head});
      out.push_back({base + "_line_wide", s, "SN 2026-000123", 0.3, ModuleStyle::line, 1000, head});
    }
  return out;
}
INSTANTIATE_TEST_SUITE_P(Codes, StylesAndHeads, testing::ValuesIn(style_cases()),
                         [](const auto& info) { return info.param.name; });

TEST(CodeDecode, InvertedAndRotatedCodesRead) {
  for (Case c : {Case{"dm_inverted", Symbology::datamatrix, "SN 0042"}, Case{"qr_inverted", Symbology::qr, "SN 0042"},
                 Case{"code128_inverted", Symbology::code128, "SN-0042", 0.2},
                 Case{"dm_rotated", Symbology::datamatrix, "SN 0042"}, Case{"qr_rotated", Symbology::qr, "SN 0042"}}) {
    c.invert = c.name.find("inverted") != std::string::npos;
    c.angle_deg = c.invert ? 0 : 33;
    expect_reads(c);
  }
}

TEST(CodeDecode, DotsTooFastForTheHeadDoNotRead) {
  // At 1 m/s a 0.25 mm dot's circle turns at ω = v/r = 8000 rad/s: on SL14 (τ = 0.21 ms) the
  // first-order lag shrinks it to 1/√(1 + (ωτ)²) ≈ 51 % of its radius.
  Case c{"fast_dots", Symbology::datamatrix, "SN 2026-000123", 0.3, ModuleStyle::dot, 1000, head_sl14()};
  const Marked fast = run(c);
  c.speed_mm_s = 100;
  const Marked slow = run(c);
  EXPECT_FALSE(fast.verification.decoded);
  EXPECT_TRUE(slow.verification.data_match);
  EXPECT_LT(fast.verification.fill_ratio.value_or(1), 0.6 * slow.verification.fill_ratio.value_or(0));
}

TEST(CodeDecode, LinesFasterThanTheMaterialMarksLeaveNothingToRead) {
  // The default material marks a 40 µm line (one spot diameter) at 1 m/s; above e² m/s ≈ 7.4 m/s
  // a line's time-averaged fluence stays under the threshold. That holds where the pulses
  // overlap (a MOPA source at 2 MHz: 4 µm apart). A Q-switched source's pulses at 30 kHz land
  // 267 µm apart, each as strong as at any speed: they mark separate dots, and no reader makes a
  // code of them.
  Case c{"too_fast", Symbology::datamatrix, "SN 0042", 0.3, ModuleStyle::square, 8000};
  c.laser.source = LaserSource::mopa;
  c.laser.frequency_khz = 2000;
  const Marked overlapping = run(c);
  EXPECT_FALSE(overlapping.verification.decoded);
  EXPECT_LT(overlapping.verification.fill_ratio.value_or(1), 0.01);

  c.laser = LaserSettings{};
  const Marked dots = run(c);
  EXPECT_FALSE(dots.verification.decoded);
  EXPECT_GT(dots.verification.fill_ratio.value_or(0), 0.03);  // the pulses' dots are on the part
  EXPECT_LT(dots.verification.fill_ratio.value_or(1), 0.15);
}

}  // namespace
}  // namespace mark
