// Production parts can be seen (issue 20): `mark --job` with --preview / --dose-png / --trace
// writes each part's files named by its serial or id, all the part's objects on one picture, and
// `job check --preview` draws the store's next part without consuming it. The pictures are read
// back with the project's PNG reader (marker/image, libpng) — not the writer's code — and their
// ink is laid against the objects' layout boxes that `job check --json` reports (computed by the
// layout, not by the picture).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "marker/image/gray_image.hpp"
#include "tests/marker/cli_runner.hpp"
#include "tests/marker/production/plates_job.hpp"

namespace mark {
namespace {

using test::run_cli;

// Two objects well apart: the serial above the x axis, a fixed lot text below it.
constexpr const char* kTwoObjects = R"({
  "format": "marker-job/1",
  "head": "SL10",
  "time_zone": "UTC",
  "counters": {"serial": {"start": 41, "width": 6}},
  "pens": {"fine": {"speed_mm_s": 800, "power_pct": 100, "frequency_khz": 40}},
  "objects": [
    {"name": "sn", "pen": "fine", "template": "SN {serial}", "height_mm": 3, "x_mm": -10, "y_mm": 4},
    {"name": "lot", "pen": "fine", "template": "LOT 7", "height_mm": 3, "x_mm": -10, "y_mm": -6}
  ]
})";

struct InkBox {
  double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
  bool empty() const { return x0 > x1; }
  void add(double x, double y) {
    x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
  }
};

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

GrayImage png(const std::filesystem::path& p) { return decode_png(slurp(p), p.string()); }

// Pixels darker than mid-grey: the ink (the preview's dose is grey to black; the part's marks
// are darker than its bare surface).
std::size_t dark_pixels(const GrayImage& g) {
  return static_cast<std::size_t>(std::count_if(g.pixels.begin(), g.pixels.end(), [](float v) { return v < 0.5f; }));
}

struct PartPicturesCli : testing::Test {
  std::filesystem::path dir = test::fresh_temp_dir("marker-part-pictures-" + std::to_string(::getpid()));
  std::string job = (dir / "two.json").string();
  void SetUp() override {
    test::use_station_state(dir);
    std::ofstream(job) << kTwoObjects;
    const auto r = run_cli({"serial", "create", "serial", "--job", job});
    ASSERT_EQ(r.code, 0) << r.err;
  }
  void TearDown() override { std::filesystem::remove_all(dir); }
  test::CliResult mark(const std::vector<std::string>& extra) { return test::run_mark_job(job, extra); }
  long long next_serial() {
    const auto r = run_cli({"serial", "show", "serial", "--job", job, "--json"});
    return nlohmann::json::parse(r.out)["next"].get<long long>();
  }
  std::string path(const std::string& name) const { return (dir / name).string(); }
  // The objects' layout boxes (stroke centre lines) as `job check` computes them.
  std::vector<InkBox> layout_boxes() {
    const auto r = run_cli({"job", "check", job, "--json"});
    EXPECT_EQ(r.code, 0) << r.err;
    std::vector<InkBox> boxes;
    const nlohmann::json check = nlohmann::json::parse(r.out);
    for (const auto& o : check["objects"]) {
      InkBox b;
      b.add(o["bounds_mm"]["x_min"], o["bounds_mm"]["y_min"]);
      b.add(o["bounds_mm"]["x_max"], o["bounds_mm"]["y_max"]);
      boxes.push_back(b);
    }
    return boxes;
  }
};

TEST_F(PartPicturesCli, TwoPartsWriteFilesNamedByTheirSerialsThatDifferWhereTheSerialDoes) {
  const auto r = mark({"--count", "2", "--json", "--preview", path("p-{serial}.png"), "--dose-png",
                       path("d-{serial}.png"), "--trace", path("t-{mark_id}.csv")});
  ASSERT_EQ(r.code, 0) << r.err;
  std::vector<nlohmann::json> parts;
  std::istringstream lines(r.out);
  for (std::string l; std::getline(lines, l);) parts.push_back(nlohmann::json::parse(l));
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0]["preview_file"], path("p-000041.png"));
  EXPECT_EQ(parts[1]["preview_file"], path("p-000042.png"));
  EXPECT_EQ(parts[1]["trace_file"], path("t-" + std::to_string(parts[1]["mark_id"].get<long long>()) + ".csv"));
  EXPECT_EQ(next_serial(), 43);

  // The previews: both parts drawn, with ink (their views differ: each holds its part's jumps).
  EXPECT_GT(dark_pixels(png(path("p-000041.png"))), 1000u);
  EXPECT_GT(dark_pixels(png(path("p-000042.png"))), 1000u);

  // The part itself (--dose-png): ink inside both objects' layout boxes, grown by the spot's
  // radius (SL10: 40 µm) and two pixels; none outside them.
  const std::vector<InkBox> boxes = layout_boxes();
  ASSERT_EQ(boxes.size(), 2u);
  const GrayImage d = png(path("d-000041.png"));
  const double px = parts[0]["dose_px_um"].get<double>() / 1000, x0 = parts[0]["dose_x0_mm"], top = parts[0]["dose_top_mm"];
  const double grow = 0.020 + 2 * px;
  std::vector<std::size_t> inside(boxes.size(), 0);
  std::size_t outside = 0;
  InkBox sn_ink, lot_ink;
  for (int y = 0; y < d.height; ++y)
    for (int x = 0; x < d.width; ++x) {
      if (d.at(x, y) >= 0.5f) continue;
      const double fx = x0 + x * px, fy = top - y * px;
      bool in_any = false;
      for (std::size_t k = 0; k < boxes.size(); ++k) {
        const InkBox& bx = boxes[k];
        if (fx >= bx.x0 - grow && fx <= bx.x1 + grow && fy >= bx.y0 - grow && fy <= bx.y1 + grow) {
          ++inside[k], in_any = true;
          (k == 0 ? sn_ink : lot_ink).add(fx, fy);
        }
      }
      outside += in_any ? 0 : 1;
    }
  EXPECT_GT(inside[0], 1000u);
  EXPECT_GT(inside[1], 1000u);
  EXPECT_EQ(outside, 0u);
  // The ink fills each box to within the spot and two pixels at every side.
  for (const auto& [ink_box, box] : {std::pair{sn_ink, boxes[0]}, std::pair{lot_ink, boxes[1]}}) {
    EXPECT_NEAR(ink_box.x0, box.x0, grow);
    EXPECT_NEAR(ink_box.x1, box.x1, grow);
    EXPECT_NEAR(ink_box.y0, box.y0, grow);
    EXPECT_NEAR(ink_box.y1, box.y1, grow);
  }

  // Part 2's picture differs from part 1's where the serial differs: laid on the field (each
  // picture's own origin), the pixels inked in one and not the other all lie in the serial's box,
  // in its right quarter (the last digit of "SN 000041" against "SN 000042"), none in the lot's.
  const GrayImage d2 = png(path("d-000042.png"));
  const double px2 = parts[1]["dose_px_um"].get<double>() / 1000, x02 = parts[1]["dose_x0_mm"],
               top2 = parts[1]["dose_top_mm"];
  const auto inked = [&](const GrayImage& g, double gpx, double gx0, double gtop, double fx, double fy) {
    const long col = std::lround((fx - gx0) / gpx), row = std::lround((gtop - fy) / gpx);
    return col >= 0 && row >= 0 && col < g.width && row < g.height && g.at(static_cast<int>(col), static_cast<int>(row)) < 0.5f;
  };
  // The last digit's box: the right quarter of the serial's box, grown as above.
  const InkBox& sn = boxes[0];
  InkBox digit;
  digit.add(sn.x1 - 0.25 * (sn.x1 - sn.x0), sn.y0 - grow);
  digit.add(sn.x1 + grow, sn.y1 + grow);
  const auto ink_in = [&](const GrayImage& g, double gpx, double gx0, double gtop, const InkBox& b, const InkBox* but) {
    std::size_t n = 0;
    for (double fy = b.y0; fy <= b.y1; fy += px)
      for (double fx = b.x0; fx <= b.x1; fx += px)
        if (!(but && fx >= but->x0 && fy >= but->y0 && fy <= but->y1) && inked(g, gpx, gx0, gtop, fx, fy)) ++n;
    return static_cast<double>(n);
  };
  InkBox lot = boxes[1], sn_grown = sn;
  lot.add(lot.x0 - grow, lot.y0 - grow), lot.add(lot.x1 + grow, lot.y1 + grow);
  sn_grown.add(sn.x0 - grow, sn.y0 - grow), sn_grown.add(sn.x1 + grow, sn.y1 + grow);
  // The lot's ink and the serial's but its last digit agree within 2 % ("LOT 7" and "SN 00004"
  // are the same text on both parts; edge pixels differ a little, since each object starts from
  // where the one before it ended, and the serials end apart); the last digit's ink differs by
  // more than 20 % ("2" is a longer stroke than "1").
  const double lot1 = ink_in(d, px, x0, top, lot, nullptr), lot2 = ink_in(d2, px2, x02, top2, lot, nullptr);
  const double sn1 = ink_in(d, px, x0, top, sn_grown, &digit), sn2 = ink_in(d2, px2, x02, top2, sn_grown, &digit);
  const double digit1 = ink_in(d, px, x0, top, digit, nullptr);
  EXPECT_GT(lot1, 500);
  EXPECT_NEAR(lot2 / lot1, 1.0, 0.02) << lot1 << " " << lot2;
  EXPECT_NEAR(sn2 / sn1, 1.0, 0.02) << sn1 << " " << sn2;
  // Where the last digit is the ink is as much but not in the same place: over 30 % of it is
  // inked on one part and not the other (52 % measured), against under 1 % on the lot (3 pixels
  // of 8886 measured: the same text, started from where a different serial ended).
  const auto xor_in = [&](const InkBox& b) {
    std::size_t n = 0;
    for (double fy = b.y0; fy <= b.y1; fy += px)
      for (double fx = b.x0; fx <= b.x1; fx += px) n += inked(d, px, x0, top, fx, fy) != inked(d2, px2, x02, top2, fx, fy);
    return static_cast<double>(n);
  };
  EXPECT_GT(xor_in(digit) / digit1, 0.3) << xor_in(digit) << " of " << digit1;
  EXPECT_LT(xor_in(lot) / lot1, 0.01) << xor_in(lot) << " of " << lot1;
}

TEST_F(PartPicturesCli, TraceSpansBothObjectsInsideTheField) {
  const auto r = mark({"--trace", path("t-{serial}.csv")});
  ASSERT_EQ(r.code, 0) << r.err;
  std::ifstream in(path("t-000041.csv"));
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "t_s,cmd_x_mm,cmd_y_mm,laser,beam_x_mm,beam_y_mm");
  const std::vector<InkBox> boxes = layout_boxes();
  ASSERT_EQ(boxes.size(), 2u);
  std::size_t rows = 0, lit_sn = 0, lit_lot = 0;
  double last_t = -1, field_half = 55;  // the job's field is 110 mm: laser-on rows within ±55 mm
  bool time_runs_on = true, in_field = true;
  for (std::string l; std::getline(in, l);) {
    double t, cx, cy, bx, by;
    int laser;
    ASSERT_EQ(std::sscanf(l.c_str(), "%lf,%lf,%lf,%d,%lf,%lf", &t, &cx, &cy, &laser, &bx, &by), 6) << l;
    ++rows;
    time_runs_on = time_runs_on && t >= last_t;
    last_t = t;
    if (!laser) continue;
    in_field = in_field && std::abs(cx) <= field_half && std::abs(cy) <= field_half;
    const auto in = [&](const InkBox& b) { return cx >= b.x0 - 0.1 && cx <= b.x1 + 0.1 && cy >= b.y0 - 0.1 && cy <= b.y1 + 0.1; };
    lit_sn += in(boxes[0]) ? 1 : 0;
    lit_lot += in(boxes[1]) ? 1 : 0;
  }
  EXPECT_GT(rows, 1000u);
  EXPECT_TRUE(time_runs_on) << "the second object's rows run on from the first's device time";
  EXPECT_TRUE(in_field);
  EXPECT_GT(lit_sn, 100u);
  EXPECT_GT(lit_lot, 100u);
}

TEST_F(PartPicturesCli, SeveralPartsWithoutAPlaceholderAreRefusedBeforeAnythingIsMarked) {
  const auto r = mark({"--count", "2", "--preview", path("p.png")});
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(r.err, "marker: --preview '" + path("p.png") +
                       "': 2 parts would write the same file: put {mark_id} or {serial} in the name "
                       "(docs/job-file.md)\n");
  EXPECT_FALSE(std::filesystem::exists(path("p.png")));
  EXPECT_EQ(next_serial(), 41);
  const auto unknown = mark({"--preview", path("p-{serail}.png")});
  EXPECT_NE(unknown.code, 0);
  EXPECT_EQ(unknown.err, "marker: --preview '" + path("p-{serail}.png") +
                             "': {serail} is not a placeholder of this job: use {mark_id}, {serial}\n");
  // What a job file says instead of --require-quality: the object's "require".
  const auto require = mark({"--require-quality", "good"});
  EXPECT_EQ(require.err, "marker: --require-quality does not apply with --job: use the object's \"require\" in the "
                         "job file (docs/job-file.md)\n");
  // One part needs no placeholder.
  EXPECT_EQ(mark({"--preview", path("one.svg")}).code, 0);
  EXPECT_TRUE(std::filesystem::exists(path("one.svg")));
}

// A picture that cannot be written does not undo the part: part 2 is marked and recorded done
// (its serial consumed), its line names the file not written, and the run stops with exit 1.
TEST_F(PartPicturesCli, AFileNotWrittenIsNamedInThePartsLineAndStopsTheRun) {
  std::filesystem::create_directories(path("p-000042.png"));  // a folder where part 2's file goes
  const auto r = mark({"--count", "3", "--preview", path("p-{serial}.png")});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("part 1/3  id 2  serial=41"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("wrote " + path("p-000041.png")), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("part 2/3  id 3  serial=42"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("done  "), std::string::npos);
  EXPECT_NE(r.out.find("; --preview NOT written: output file '" + path("p-000042.png") + "'"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("part 3/3"), std::string::npos) << r.out;
  EXPECT_EQ(r.err.substr(r.err.find("marker: part 2")),
            "marker: part 2 (id 3) is done as recorded; a file of it was not written: no further part started\n");
  EXPECT_EQ(next_serial(), 43);
}

TEST_F(PartPicturesCli, JobCheckPreviewDrawsTheStoresNextPartWithoutConsumingIt) {
  ASSERT_EQ(mark({"--preview", path("m-{serial}.png")}).code, 0);  // part 41
  ASSERT_EQ(next_serial(), 42);
  const auto c = run_cli({"job", "check", job, "--preview", path("check.png"), "--json"});
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_EQ(nlohmann::json::parse(c.out)["objects"][0]["text"], "SN 000042");
  EXPECT_EQ(next_serial(), 42);  // nothing consumed
  ASSERT_EQ(mark({"--preview", path("m-{serial}.png")}).code, 0);  // part 42, as job check drew it
  const GrayImage check = png(path("check.png")), m42 = png(path("m-000042.png")), m41 = png(path("m-000041.png"));
  ASSERT_EQ(check.width, m42.width);
  ASSERT_EQ(check.height, m42.height);
  // The same part on the same simulated head: the pictures agree pixel for pixel (0 differ,
  // measured) but for at most 0.1 % of the ink; part 41's differs from it by more (its last digit).
  const auto differing = [](const GrayImage& x, const GrayImage& y) {
    std::size_t n = 0;
    for (std::size_t i = 0; i < x.pixels.size(); ++i) n += std::abs(x.pixels[i] - y.pixels[i]) > 0.25f ? 1 : 0;
    return n;
  };
  const std::size_t ink = dark_pixels(check);
  EXPECT_LE(differing(check, m42), ink / 1000) << "ink " << ink;
  // Part 41's ends its serial elsewhere: its jumps, and so its view, differ, or its pixels do.
  if (check.pixels.size() == m41.pixels.size()) {
    EXPECT_GT(differing(check, m41), ink / 50) << "ink " << ink;
  }
}

// With a data list the next part is the store's next untaken row, not the list's first: a part
// marked takes row 1 ("VIN-A"), and `job check --preview` then shows row 2's text and says so.
TEST_F(PartPicturesCli, JobCheckPreviewTakesTheStoresNextDataListRow) {
  test::write_plates_list(dir);
  std::ofstream(job) << test::kPlatesJob;
  const auto first = run_cli({"job", "check", job, "--preview", path("c1.png"), "--json"});
  ASSERT_EQ(first.code, 0) << first.err;
  EXPECT_EQ(nlohmann::json::parse(first.out)["objects"][0]["text"], "VIN-A 000041");
  EXPECT_EQ(nlohmann::json::parse(first.out)["data_row"], 1);
  const auto m = mark({"--json"});
  ASSERT_EQ(m.code, 0) << m.err;
  const auto c = run_cli({"job", "check", job, "--preview", path("c2.png"), "--json"});
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_EQ(nlohmann::json::parse(c.out)["objects"][0]["text"], "VIN-B 000042");
  EXPECT_EQ(nlohmann::json::parse(c.out)["data_row"], 2);
  ASSERT_EQ(mark({"--json"}).code, 0);  // row 2 taken as job check drew it
  const auto none = run_cli({"job", "check", job, "--preview", path("c3.png")});
  EXPECT_EQ(none.code, 1);  // job check: the job cannot be marked
  EXPECT_NE(none.err.find("--preview: data list plates.csv: every row was taken by an earlier part (2 rows in the file): "
                           "the next part would be refused"),
            std::string::npos)
      << none.err;
  EXPECT_FALSE(std::filesystem::exists(path("c3.png")));
}

}  // namespace
}  // namespace mark
