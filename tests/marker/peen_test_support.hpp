#pragma once
// Shared fixtures of the dot-peen tests: the patent's timing case, a 12-character serial number,
// small hand-drawn dot matrices, and the check that a plan strikes every dot exactly once.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string_view>
#include <vector>

#include "marker/peen/dot_fonts.hpp"
#include "marker/peen/dot_layout.hpp"
#include "marker/peen/peen_plan.hpp"
#include "marker/peen/planners.hpp"

namespace mark::peen_test {

// Seven 10x16 "8" characters, 12 mm high (0.8 mm pitch, 60 mm long), centred in the patent's
// 63 x 38 mm marking window.
inline DotText patent_eights() {
  LayoutOptions o;
  o.height_mm = 12;
  o.align = Align::center;
  o.base = Point(0, -6);
  return layout_dot_text("8888888", dot_font_10x16(), o);
}

// A 12-character serial number in the 5x7 font at Telesis' 3.175 mm, centred in the field.
inline constexpr std::string_view kSerial = "AB12-345678C";
inline DotText serial_5x7(double height_mm = 3.175) {
  LayoutOptions o;
  o.height_mm = height_mm;
  o.align = Align::center;
  o.base = Point(0, -height_mm / 2);
  return layout_dot_text(kSerial, dot_font_5x7(), o);
}

inline Box patent_window() { return centred_window(63, 38); }

// One character drawn as rows ('#' a dot), cell (c, r) at (c·pitch, −r·pitch) mm.
inline DotText matrix_text(std::initializer_list<std::string_view> rows, double pitch_mm = 1.0) {
  DotText t;
  t.pitch_mm = pitch_mm;
  t.characters = 1;
  Affine frame = Affine::Identity();
  frame.linear() << pitch_mm, 0.0, 0.0, -pitch_mm;
  t.cell_frames.push_back(frame);
  int r = 0;
  for (std::string_view row : rows) {
    for (int c = 0; c < static_cast<int>(row.size()); ++c)
      if (row[static_cast<std::size_t>(c)] == '#')
        t.dots.push_back({frame * Point(c, r), 0, {c, r}});
    ++r;
  }
  return t;
}

// The cells struck, in order (turn points left out).
inline std::vector<DotCell> struck_cells(const DotText& text, const PeenPlan& plan) {
  std::vector<DotCell> out;
  for (const PlanStop& s : plan.stops)
    if (s.dot) out.push_back(text.dots.at(*s.dot).cell);
  return out;
}

// Every dot of the text is struck exactly once, at its own position, and nothing else is struck.
inline void expect_each_dot_once(const DotText& text, const PeenPlan& plan) {
  std::vector<int> hits(text.dots.size(), 0);
  for (const PlanStop& s : plan.stops) {
    if (!s.dot) continue;
    ASSERT_LT(*s.dot, text.dots.size()) << plan.planner;
    ++hits[*s.dot];
    EXPECT_LT((s.pos_mm - text.dots[*s.dot].pos_mm).norm(), 1e-12) << plan.planner;
  }
  for (std::size_t i = 0; i < hits.size(); ++i)
    EXPECT_EQ(hits[i], 1) << plan.planner << ": dot " << i << " struck " << hits[i] << " times";
}

}  // namespace mark::peen_test
