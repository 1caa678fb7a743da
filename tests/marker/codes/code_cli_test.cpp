// `marker code` end to end, in-process, and the fill options of `layout` / `preview`: JSON
// figures with units in their keys, the dose picture with its pixel size, exit 2 when the mark
// does not read, and one-line errors naming option, value and range, with no file left behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "tests/driver/png_info.hpp"
#include "tests/marker/cli_runner.hpp"

namespace mark {
namespace {

namespace fs = std::filesystem;
fs::path temp_file(const std::string& name) { return test::fresh_temp_file("marker_code_cli_test", name); }

TEST(CodeCli, JsonReportsTheDecodedDataAndTheFigures) {
  const fs::path png = temp_file("gs1.png");
  const test::CliResult r =
      test::run_cli({"code", "gs1-datamatrix", "(01)09506000134352(17)261231(10)LOT42(21)SN0001", "--size", "5",
                     "--json", "--dose-png", png.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["symbology"], "gs1-datamatrix");
  EXPECT_EQ(j["data"], "(01)09506000134352(17)261231(10)LOT42(21)SN0001");
  EXPECT_EQ(j["decoded"], true);
  EXPECT_EQ(j["data_match"], true);
  EXPECT_EQ(j["decoded_data"], "01095060001343521726123110LOT42\x1d" "21SN0001");
  EXPECT_EQ(j["rows"], 22);
  EXPECT_NEAR(j["module_um"].get<double>(), 5000.0 / 22, 1e-9);
  EXPECT_NEAR(j["module_x_um"].get<double>(), 5000.0 / 22, 10);
  // Both Data Matrix readers read it; ZBar does not read Data Matrix.
  EXPECT_EQ(j["decided_by"], "any two");
  ASSERT_EQ(j["readers"].size(), 3u);
  EXPECT_EQ(j["readers"][0]["reader"], "zxing");
  EXPECT_EQ(j["readers"][0]["data_match"], true);
  EXPECT_EQ(j["readers"][1]["reader"], "libdmtx");
  EXPECT_EQ(j["readers"][1]["data_match"], true);
  EXPECT_EQ(j["readers"][2]["supported"], false);
  // A clean mark grades A on every TR 29158 parameter; the grid fitted matches the module.
  ASSERT_TRUE(j["iso"].is_object());
  EXPECT_EQ(j["iso"]["standard"], "ISO/IEC TR 29158");
  for (const char* k : {"overall", "decode", "cell_contrast", "cell_modulation", "fixed_pattern_damage",
                        "axial_nonuniformity", "grid_nonuniformity", "unused_error_correction"})
    EXPECT_EQ(j["iso"][k], "A") << k;
  EXPECT_NEAR(j["iso"]["module_x_px"].get<double>() * j["camera_px_um"].get<double>(), 5000.0 / 22, 10);
  EXPECT_EQ(j["iso"]["codewords_wrong"], 0);
  for (const char* k : {"fill_ratio", "fill_ratio_min", "spill_ratio", "modules_wrong", "camera_px_um", "mark_time_s",
                        "hatch_lines", "speed_mm_s", "width_mm", "quiet_zone_modules"})
    EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_DOUBLE_EQ(j["dose_px_um"].get<double>(), 5.0);
  ASSERT_TRUE(fs::exists(png));
  // Readable PNG of the code's window with its pixel size.
  const test::PngInfo info = test::read_png_info(png.string());
  ASSERT_TRUE(info.read);
  EXPECT_EQ(info.ppm_x, 200000u);
  const double width_mm = info.width * 1000.0 / info.ppm_x;
  EXPECT_GT(width_mm, 5.0 + 2 * 5.0 / 22);  // the symbol and its quiet zone at least
}

TEST(CodeCli, TextSummaryAndExitTwoWhenTheMarkDoesNotRead) {
  const test::CliResult ok = test::run_cli({"code", "qr", "SN 0042"});
  ASSERT_EQ(ok.code, 0) << ok.err;
  EXPECT_NE(ok.out.find("zxing reads; libdmtx n/a; zbar reads; PASS, 'SN 0042'"), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find("ISO/IEC TR 29158 grade A"), std::string::npos) << ok.out;
  // Far above the material's vanishing speed (7.4 m/s) the lines leave no mark a reader finds:
  // the code fails and grades F.
  const test::CliResult fast = test::run_cli({"code", "datamatrix", "SN 0042", "--speed", "12000", "--head", "SL10"});
  EXPECT_EQ(fast.code, 2) << fast.out << fast.err;
  EXPECT_NE(fast.out.find("; FAIL"), std::string::npos) << fast.out;
  EXPECT_NE(fast.out.find("grade F"), std::string::npos) << fast.out;
  // A mark of less contrast (reflectance 0.40 against 0.55: cell contrast 1 − 0.40/0.55 = 27 %,
  // grade B) reads but falls short of a required A: exit 2, the reason on stderr.
  const test::CliResult faint =
      test::run_cli({"code", "qr", "SN 0042", "--camera", "mark_reflectance=0.40", "--require-grade", "A"});
  EXPECT_EQ(faint.code, 2) << faint.out << faint.err;
  EXPECT_NE(faint.out.find("PASS"), std::string::npos) << faint.out;
  EXPECT_NE(faint.err.find("cell contrast"), std::string::npos) << faint.err;
  EXPECT_NE(faint.out.find("cell contrast B (27 %)"), std::string::npos) << faint.out;
  EXPECT_EQ(test::run_cli({"code", "qr", "SN 0042", "--camera", "mark_reflectance=0.40", "--require-grade", "B"}).code, 0);
}

TEST(CodeCli, OptionsOutsideTheirRangesAreOneLineErrors) {
  const fs::path png = temp_file("never.png");
  struct Bad {
    std::vector<std::string> args;
    std::string message;
  };
  for (const Bad& b : std::vector<Bad>{
           {{"--module", "0"}, "--module: 0 is outside the range 0.01 to 20 mm"},
           {{"--module", "0.3", "--size", "4"}, "give --size or --module, not both"},
           {{"--hatch-spacing", "-1"}, "--hatch-spacing: -1 is outside the range 0.001 to 10 mm"},
           {{"--speed", "0"}, "--speed: 0 is outside the range "},
           {{"--beam-diameter", "9"}, "--beam-diameter: 9 is outside the range 0.001 to 5 mm"},
           {{"--camera", "f_number=0.1"}, "--camera f_number: 0.1 is outside the range 0.7 to 64"},
           {{"--camera", "zoom=2"}, "--camera: unknown key 'zoom' (keys: pixel_um, "},
           {{"--camera", "seed=1.5"}, "--camera seed: '1.5' is not a whole number"},
           {{"--reader", "zbar"}, "--reader zbar does not read datamatrix"},
           {{"--require-grade", "E"}, "--require-grade: 'E' is not one of A, B, C, D"},
           {{"--style", "star"}, "--style: 'star' is not one of square, dot, line"},
           {{"--matrix-size", "11x11"}, "Data Matrix size 11x11 is not an ECC 200 size"},
           {{"--x", "60"}, "code 1 with its quiet zone leaves the field"},
           {{"--head", "XY"}, "--head 'XY' is not one of SL10, SL14, cheap"}}) {
    std::vector<std::string> args = {"code", "datamatrix", "SN 0042", "--dose-png", png.string()};
    args.insert(args.end(), b.args.begin(), b.args.end());
    const test::CliResult r = test::run_cli(args);
    EXPECT_EQ(r.code, 1) << b.args[0];
    EXPECT_NE(r.err.find(b.message), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(png));
  }
  const test::CliResult sym = test::run_cli({"code", "pdf417", "X"});
  EXPECT_EQ(sym.err, "marker: symbology 'pdf417' is not one of datamatrix, gs1-datamatrix, qr, code128, gs1-128\n");
}

TEST(FillCli, LayoutJsonCarriesTheFillFigures) {
  const test::CliResult r = test::run_cli({"layout", "SN 42", "--font", "DejaVuSans", "--height", "3", "--fill", "hatch",
                                           "--hatch-angle", "0,90", "--contour-passes", "1", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("fill"));
  EXPECT_GT(j["fill"]["hatch_lines"].get<int>(), 100);
  EXPECT_EQ(j["fill"]["contour_loops"].get<int>(), 5);  // S, N, 2 and the 4 with its counter
  EXPECT_GT(j["fill"]["area_mm2"].get<double>(), 1.0);
}

TEST(FillCli, SingleLineFontAndBadOptionsAreRefused) {
  const fs::path svg = temp_file("never.svg");
  const test::CliResult stroke = test::run_cli({"preview", "A", "--fill", "hatch", "-o", svg.string()});
  EXPECT_EQ(stroke.code, 1);
  EXPECT_NE(stroke.err.find("only closed outlines can be filled"), std::string::npos) << stroke.err;
  const test::CliResult rule = test::run_cli({"preview", "A", "--font", "DejaVuSans", "--fill", "hatch", "--fill-rule", "odd",
                                              "-o", svg.string()});
  EXPECT_EQ(rule.err, "marker: --fill-rule: 'odd' is not one of nonzero, evenodd\n");
  const test::CliResult mode = test::run_cli({"preview", "A", "--font", "DejaVuSans", "--fill", "cross", "-o", svg.string()});
  EXPECT_EQ(mode.err, "marker: --fill: 'cross' is not one of none, hatch\n");
  EXPECT_FALSE(fs::exists(svg));
}

}  // namespace
}  // namespace mark

namespace mark {
namespace {

TEST(MarkCodeCli, FilledTextWithAUdiCodeReadsBackAndReportsTheCode) {
  const fs::path png = test::fresh_temp_file("marker_code_cli_test", "mark.png");
  const test::CliResult r = test::run_cli(
      {"mark", "SN 000042", "--font", "DejaVuSans", "--height", "3", "--fill", "hatch", "--code",
       "gs1-datamatrix:(01)09506000134352(21)000042", "--code-x", "26", "--code-y", "1.5", "--code-module",
       "0.3", "--virtual-time", "--json", "--dose-png", png.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["outcome"], "done");
  EXPECT_EQ(j["quality"]["class"], "high");
  ASSERT_EQ(j["codes"].size(), 1u);
  const auto& c = j["codes"][0];
  EXPECT_EQ(c["symbology"], "gs1-datamatrix");
  EXPECT_EQ(c["decoded"], true);
  EXPECT_EQ(c["data_match"], true);
  EXPECT_EQ(c["decoded_data"], "0109506000134352" "21000042");
  EXPECT_DOUBLE_EQ(c["module_um"].get<double>(), 300);
  EXPECT_GT(c["fill_ratio"].get<double>(), 0.8);
  const test::PngInfo info = test::read_png_info(png.string());
  ASSERT_TRUE(info.read);
  EXPECT_NEAR(1e6 / info.ppm_x, j["dose_px_um"].get<double>(), 1e-9);
  // Text and code both in the picture: wider than the code's 26 mm centre.
  EXPECT_GT(info.width * j["dose_px_um"].get<double>() / 1000, 28.0);
}

TEST(MarkCodeCli, ACodeAloneAndTheRefusals) {
  const test::CliResult alone = test::run_cli({"mark", "", "--code", "qr:HELLO", "--virtual-time", "--json"});
  ASSERT_EQ(alone.code, 0) << alone.err;
  EXPECT_EQ(nlohmann::json::parse(alone.out)["codes"][0]["data_match"], true);
  const test::CliResult overlap = test::run_cli({"mark", "SN 000042", "--font", "DejaVuSans", "--height", "3", "--code",
                                                 "datamatrix:SN000042", "--code-x", "12", "--virtual-time"});
  EXPECT_EQ(overlap.code, 1);
  EXPECT_NE(overlap.err.find("code 1: its quiet zone is marked by the text"), std::string::npos) << overlap.err;
  const test::CliResult bad = test::run_cli({"mark", "X", "--code", "datamatrix", "--virtual-time"});
  EXPECT_EQ(bad.err, "marker: --code 'datamatrix': expected SYMBOLOGY:DATA, e.g. datamatrix:SN0042\n");
  const test::CliResult module = test::run_cli({"mark", "X", "--code", "qr:A", "--code-module", "0", "--virtual-time"});
  EXPECT_EQ(module.err, "marker: --code-module: 0 is outside the range 0.01 to 20 mm\n");
  const test::CliResult empty = test::run_cli({"mark", "", "--virtual-time"});
  EXPECT_EQ(empty.err, "marker: mark: give the text to mark (or --code), or --job FILE\n");
  // A code that the simulator says will not read is refused before firing when asked.
  const test::CliResult unreadable = test::run_cli({"mark", "", "--code", "datamatrix:SN1", "--speed", "8000",
                                                    "--require-quality", "good", "--virtual-time"});
  EXPECT_EQ(unreadable.code, 1);
  EXPECT_NE(unreadable.err.find("--require-quality good: the simulator predicts code 1 not decoded by"), std::string::npos)
      << unreadable.err;
}

TEST(MarkCodeCli, RequireGradeRefusesACodeBelowItBeforeFiring) {
  // The same clean QR graded off the predicted mark: with a mark of reflectance 0.40 on a 0.55
  // part its cell contrast is 1 − 0.40/0.55 = 27 %, grade B, so A is refused and B is met.
  const std::vector<std::string> base = {"mark", "", "--code", "qr:SN 0042", "--camera", "mark_reflectance=0.40",
                                         "--virtual-time", "--json"};
  std::vector<std::string> strict = base, met = base;
  strict.insert(strict.end(), {"--require-grade", "A"});
  met.insert(met.end(), {"--require-grade", "B"});
  const test::CliResult refused = test::run_cli(strict);
  EXPECT_EQ(refused.code, 1);
  EXPECT_EQ(refused.err,
            "marker: --require-grade A: the simulator predicts code 1 (qr 21x21): grade B (cell contrast B); nothing "
            "was fired\n");
  EXPECT_TRUE(refused.out.empty()) << "nothing ran";
  const test::CliResult done = test::run_cli(met);
  ASSERT_EQ(done.code, 0) << done.err;
  const auto j = nlohmann::json::parse(done.out);
  EXPECT_EQ(j["outcome"], "done");
  EXPECT_EQ(j["codes"][0]["iso"]["overall"], "B");
  EXPECT_EQ(j["codes"][0]["iso"]["cell_contrast"], "B");
  EXPECT_NEAR(j["codes"][0]["iso"]["cell_contrast_fraction"].get<double>(), 1 - 0.40 / 0.55, 0.03);
  const test::CliResult no_code = test::run_cli({"mark", "X", "--require-grade", "B", "--virtual-time"});
  EXPECT_EQ(no_code.err, "marker: --require-grade B: the job marks no code (give --code)\n");
}

}  // namespace
}  // namespace mark
