#pragma once
// Helpers shared by the font-loader tests.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <string_view>

#include "fonts/element.hpp"
#include "fonts/error.hpp"
#include "fonts/glyph.hpp"
#include "fonts/loaders.hpp"

namespace mark::test {

inline const std::string kHersheyDir = "/usr/share/hershey-fonts";
inline const std::string kLibreCadDir = "/usr/share/librecad/fonts";
inline const std::string kDataDir = std::string(MARKER_SOURCE_DIR) + "/tests/fonts/data";

// Runs `parse` and checks it throws FontFileError "<source>:<line>: ..." containing `fragment`.
template <class Parse>
void expect_font_error(Parse&& parse, const std::string& source, std::size_t line,
                       std::string_view fragment) {
  try {
    parse();
    ADD_FAILURE() << "no FontFileError; expected line " << line << " '" << fragment << "'";
  } catch (const FontFileError& e) {
    const std::string what = e.what();
    const std::string prefix = source + ":" + std::to_string(line) + ": ";
    EXPECT_EQ(what.rfind(prefix, 0), 0u) << what << "\n  expected prefix: " << prefix;
    EXPECT_NE(what.find(fragment), std::string::npos) << what << "\n  expected: " << fragment;
  }
}

// The lit elements of a glyph, and the laser-off ones.
inline std::size_t count_lit(const Glyph& g) {
  std::size_t n = 0;
  for (const Element& e : g.elements) n += e.laser();
  return n;
}
inline std::size_t count_travel(const Glyph& g) { return g.elements.size() - count_lit(g); }

inline void expect_point(const Point& actual, double x, double y, double tol = 1e-12) {
  EXPECT_NEAR(actual.x(), x, tol) << "point (" << actual.x() << ", " << actual.y() << ")";
  EXPECT_NEAR(actual.y(), y, tol) << "point (" << actual.x() << ", " << actual.y() << ")";
}

// Every element starts where the one before it ended (travel included): the glyph is one
// continuous path of the pen.
inline void expect_continuous(const Glyph& g, double tol = 1e-9) {
  for (std::size_t i = 1; i < g.elements.size(); ++i)
    EXPECT_LE((g.elements[i].start() - g.elements[i - 1].end()).norm(), tol)
        << "gap before element " << i << " of U+" << std::hex
        << static_cast<unsigned>(g.code_point);
}

}  // namespace mark::test
