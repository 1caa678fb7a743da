// GET /api/preview.png (issue 20): the next part's picture, PNG, the same bytes as
// `marker job check --preview` draws for the same store and job (one function behind both),
// changed after a part is marked and nothing consumed by asking for it. Read back with the
// project's PNG reader (libpng) to check it is a picture with ink, not only bytes.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "marker/image/gray_image.hpp"
#include "tests/marker/cli_runner.hpp"
#include "tests/marker/station/served_station.hpp"
// Last: it brings <resolv.h>, whose `_res` macro breaks Eigen's headers included after it.
#include <httplib.h>

namespace mark {
namespace {

std::string job_check_preview(const test::Served& s, const std::string& name) {
  const std::string out = (s.dir / name).string();
  const auto r = test::run_cli({"job", "check", (s.dir / "line.json").string(), "--preview", out, "--store", s.store_path});
  EXPECT_EQ(r.code, 0) << r.err;
  std::ifstream in(out, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

TEST(StationHttp, PreviewPngIsJobChecksPictureOfTheNextPartAndChangesAfterAMark) {
  test::Served s;
  httplib::Client c("127.0.0.1", s.http_port());
  c.set_read_timeout(std::chrono::seconds(60));
  auto first = c.Get("/api/preview.png");
  ASSERT_TRUE(first);
  EXPECT_EQ(first->status, 200);
  EXPECT_EQ(first->get_header_value("Content-Type"), "image/png");
  EXPECT_EQ(first->body, job_check_preview(s, "check-41.png"));
  const GrayImage picture = decode_png(first->body, "/api/preview.png");
  const auto ink = std::count_if(picture.pixels.begin(), picture.pixels.end(), [](float v) { return v < 0.5f; });
  EXPECT_GT(ink, 1000);
  // Asking consumed nothing.
  EXPECT_EQ(nlohmann::json::parse(c.Get("/api/serial/serial")->body)["next"], 41);

  ASSERT_EQ(c.Post("/api/mark")->status, 200);
  auto second = c.Get("/api/preview.png");
  ASSERT_TRUE(second);
  EXPECT_EQ(second->status, 200);
  EXPECT_NE(second->body, first->body);
  EXPECT_EQ(second->body, job_check_preview(s, "check-42.png"));
  test::expect_one_part(s.close(), 2, 41, Outcome::done);
}

}  // namespace
}  // namespace mark
