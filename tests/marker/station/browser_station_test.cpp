// The operator page in a real browser (issue 22): headless Debian chromium, driven through
// chromedriver's WebDriver, loads the page from a station serving the simulated scanner, shows
// the next mark's picture, pauses and resumes with its buttons, and marks a part with its Mark
// button. What the page shows is checked against the store read back after the station closed,
// and the screenshot is decoded to pixels. The Node harness (StationHttpToken) runs the page's
// script on a fake DOM; this runs the page as an operator's browser does, layout and all.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "marker/image/gray_image.hpp"
#include "tests/marker/cli_runner.hpp"
#include "tests/marker/station/served_station.hpp"
// Last: it brings <httplib.h> (see there).
#include "tests/marker/station/webdriver_session.hpp"

namespace mark {
namespace {

using test::Served;
using test::WebDriverSession;
using namespace std::chrono_literals;

constexpr int kWidth = 1000, kHeight = 1400;

// The text of the element with id `id`, as the page shows it.
std::string shown(WebDriverSession& b, const std::string& id) {
  return b.run("return document.getElementById('" + id + "').textContent;").get<std::string>();
}

TEST(StationBrowser, OperatorPageMarksAPartInHeadlessChromium) {
  if (!test::browser_installed()) GTEST_SKIP() << "chromium and chromium-driver (Debian) are not installed";
  Served s;
  const auto dir = test::fresh_temp_dir("marker_browser");
  const std::string page = "http://127.0.0.1:" + std::to_string(s.http_port()) + "/";
  {
    WebDriverSession b(dir / "chromedriver.log", kWidth, kHeight);
    b.navigate(page);

    // The page reads the state, the next part and its picture from the station.
    ASSERT_TRUE(b.wait_for("document.getElementById('state').textContent === 'idle' && "
                           "document.getElementById('picture').complete && "
                           "document.getElementById('picture').naturalWidth > 0",
                           30s))
        << "state " << shown(b, "state") << "; " << b.log_text();
    EXPECT_EQ(shown(b, "next"), "SN 000041 LOT A00");
    EXPECT_GT(b.run("return document.getElementById('picture').naturalHeight;").get<int>(), 0);

    // Pause, then Resume (the same button, relabelled): the station's own state follows.
    b.click("#pause");
    ASSERT_TRUE(b.wait_for("document.getElementById('state').textContent === 'paused'", 30s)) << shown(b, "state");
    EXPECT_EQ(s.station->status().state, StationState::paused);
    ASSERT_TRUE(b.wait_for("document.getElementById('pause').textContent === 'Resume'", 30s));
    b.click("#pause");
    ASSERT_TRUE(b.wait_for("document.getElementById('state').textContent === 'idle'", 30s)) << shown(b, "state");
    EXPECT_EQ(s.station->status().state, StationState::idle);

    // Mark: the page hears the part end on its event stream and shows it, and its log table
    // gains the row.
    const std::string first_picture = b.run("return document.getElementById('picture').src;").get<std::string>();
    b.click("#mark");
    ASSERT_TRUE(b.wait_for("document.getElementById('last_outcome').textContent === 'done'", 60s))
        << "outcome " << shown(b, "last_outcome") << ", message " << shown(b, "message");
    EXPECT_EQ(shown(b, "last_id"), "2");
    EXPECT_EQ(shown(b, "last_serials"), "serial = 41");
    EXPECT_EQ(shown(b, "last_text"), "SN 000041 LOT A00");
    ASSERT_TRUE(b.wait_for("document.querySelector('#log tbody tr') !== null", 30s));
    const auto row = b.run(
        "return Array.from(document.querySelectorAll('#log tbody tr:first-child td')).map(c => c.textContent);");
    ASSERT_EQ(row.size(), 5u);
    EXPECT_EQ(row[0].get<std::string>(), "2");
    EXPECT_EQ(row[2].get<std::string>(), "SN 000041 LOT A00");
    EXPECT_EQ(row[3].get<std::string>(), "serial=41");
    EXPECT_EQ(row[4].get<std::string>(), "done");
    // The next part is the next serial once the page has refreshed.
    ASSERT_TRUE(b.wait_for("document.getElementById('next').textContent === 'SN 000042 LOT A00'", 30s))
        << shown(b, "next");
    // ... and its picture is drawn afresh for it (a new image, loaded).
    ASSERT_TRUE(b.wait_for("document.getElementById('picture').src !== '" + first_picture +
                               "' && document.getElementById('picture').complete && "
                               "document.getElementById('picture').naturalWidth > 0",
                           30s));

    // The screenshot: a PNG of the window's size, with the page drawn on it (dark text on a
    // light page: not one flat colour).
    const GrayImage shot = decode_png(b.screenshot(), "screenshot");
    EXPECT_EQ(shot.width, kWidth);
    EXPECT_GE(shot.height, kHeight / 2);
    const auto dark = std::count_if(shot.pixels.begin(), shot.pixels.end(), [](float v) { return v < 0.5f; });
    const double dark_share = static_cast<double>(dark) / static_cast<double>(shot.pixels.size());
    EXPECT_GT(dark_share, 0.001);
    EXPECT_LT(dark_share, 0.9);
  }
  // The store, read after the station closed, holds the one part the page showed.
  test::expect_one_part(s.close(), 2, 41, Outcome::done, "SN 000041 LOT A00");
  std::filesystem::remove_all(dir);
}

// With `--token`: the page shows its login on the first 401, the operator types the token into
// the password field and submits the form; the page then shows the station and marks a part.
TEST(StationBrowser, OperatorPageAsksForTheTokenInHeadlessChromium) {
  if (!test::browser_installed()) GTEST_SKIP() << "chromium and chromium-driver (Debian) are not installed";
  constexpr const char* kToken = "Hc7pW2qZ9vKx4Lm8Rt3N";
  Served s(true, 8, {}, kToken);
  const auto dir = test::fresh_temp_dir("marker_browser_token");
  {
    WebDriverSession b(dir / "chromedriver.log", kWidth, kHeight);
    b.navigate("http://127.0.0.1:" + std::to_string(s.http_port()) + "/");
    ASSERT_TRUE(b.wait_for("!document.getElementById('login').hidden", 30s)) << b.log_text();
    EXPECT_EQ(shown(b, "message"), "this station needs its token");
    EXPECT_EQ(shown(b, "state"), "…");  // nothing of the station shown without the token

    b.type("#token", kToken);
    b.click("#login button[type=submit]");
    ASSERT_TRUE(b.wait_for("document.getElementById('state').textContent === 'idle' && "
                           "document.getElementById('next').textContent === 'SN 000041 LOT A00'",
                           30s))
        << "state " << shown(b, "state") << ", message " << shown(b, "message");
    EXPECT_EQ(b.run("return document.getElementById('token').value;").get<std::string>(), "");  // not left in the form

    b.click("#mark");
    ASSERT_TRUE(b.wait_for("document.getElementById('last_outcome').textContent === 'done'", 60s))
        << "outcome " << shown(b, "last_outcome") << ", message " << shown(b, "message");
    EXPECT_EQ(shown(b, "last_text"), "SN 000041 LOT A00");
  }
  test::expect_one_part(s.close(), 2, 41, Outcome::done, "SN 000041 LOT A00");
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace mark
