// The laser delay line shifts laser-on edges by on_delay and laser-off edges by off_delay ticks,
// to the tick and across block boundaries, never moves a coordinate, drops pulses that become
// empty, merges pulses that overlap, and leaves the laser off at the end of the stream.
#include "ringbuffer/laser_delay_line.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace mark {
namespace {

// A stream whose laser is on exactly on the ticks in `lit` ([begin, end) pairs); x = tick.
std::vector<ScanSample> stream(std::size_t n, std::vector<std::pair<int, int>> lit) {
  std::vector<ScanSample> s(n);
  for (std::size_t i = 0; i < n; ++i) {
    s[i].x_mm = static_cast<float>(i);
    s[i].y_mm = -static_cast<float>(i);
  }
  for (auto [a, b] : lit)
    for (int i = a; i < b; ++i) s[static_cast<std::size_t>(i)].laser = true;
  return s;
}

// Run the delay line over `in` in blocks of the given sizes (cycled), then flush.
std::vector<ScanSample> run(LaserDelayLine& line, std::vector<ScanSample> in,
                            std::vector<std::size_t> blocks) {
  std::size_t pos = 0, b = 0;
  while (pos < in.size()) {
    const std::size_t n = std::min(blocks[b++ % blocks.size()], in.size() - pos);
    line.apply(std::span<ScanSample>(in.data() + pos, n));
    pos += n;
  }
  std::vector<ScanSample> tail;
  line.flush(in.empty() ? ScanSample{} : in.back(), tail);
  in.insert(in.end(), tail.begin(), tail.end());
  return in;
}

std::vector<int> lit_ticks(const std::vector<ScanSample>& s) {
  std::vector<int> t;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s[i].laser) t.push_back(static_cast<int>(i));
  return t;
}

std::vector<int> range(int a, int b) {
  std::vector<int> r;
  for (int i = a; i < b; ++i) r.push_back(i);
  return r;
}

TEST(LaserDelayLine, ShiftsOnAndOffEdgesIndependentlyAcrossBlocks) {
  for (std::vector<std::size_t> blocks : {std::vector<std::size_t>{1}, {3}, {7, 1, 100}, {1000}}) {
    LaserDelayLine line(3, 5);
    const auto out = run(line, stream(60, {{10, 30}, {40, 45}}), blocks);
    std::vector<int> want = range(13, 35);
    for (int i : range(43, 50)) want.push_back(i);
    EXPECT_EQ(lit_ticks(out), want);
    ASSERT_EQ(out.size(), 60u);  // nothing owed: the stream ended dark long enough
    for (std::size_t i = 0; i < out.size(); ++i) {
      EXPECT_EQ(out[i].x_mm, static_cast<float>(i));  // coordinates never move
      EXPECT_EQ(out[i].y_mm, -static_cast<float>(i));
    }
  }
}

TEST(LaserDelayLine, ZeroDelaysPassTheLaserThrough) {
  LaserDelayLine line(0, 0);
  EXPECT_EQ(lit_ticks(run(line, stream(20, {{0, 4}, {9, 12}}), {5})),
            (std::vector<int>{0, 1, 2, 3, 9, 10, 11}));
}

TEST(LaserDelayLine, PulseShorterThanDelayDifferenceIsDropped) {
  // on 8, off 2: the 4-tick pulse [10,14) would become [18,16): empty, so no light at all —
  // never an on edge after its own off edge.
  LaserDelayLine line(8, 2);
  const auto out = run(line, stream(40, {{10, 14}, {25, 35}}), {4});
  EXPECT_EQ(lit_ticks(out), range(33, 37));
  // A pulse exactly as long as the difference is empty too; one tick longer gives one tick.
  LaserDelayLine a(8, 2), b(8, 2);
  EXPECT_TRUE(lit_ticks(run(a, stream(40, {{10, 16}}), {5})).empty());
  EXPECT_EQ(lit_ticks(run(b, stream(40, {{10, 17}}), {5})), (std::vector<int>{18}));
}

TEST(LaserDelayLine, GapShorterThanDelayDifferenceMerges) {
  // on 1, off 6: pulses [10,20) and [23,30) become [11,26) and [24,36): one continuous pulse.
  LaserDelayLine line(1, 6);
  EXPECT_EQ(lit_ticks(run(line, stream(50, {{10, 20}, {23, 30}}), {2})), range(11, 36));
}

TEST(LaserDelayLine, FlushPlaysThePendingOffAndEndsDark) {
  // The stream ends lit at tick 10: the delayed off falls at tick 14, so the tail holds the last
  // position lit for ticks 10..13 and ends with the laser off at tick 14.
  LaserDelayLine line(2, 4);
  const auto out = run(line, stream(10, {{5, 10}}), {3});
  ASSERT_EQ(out.size(), 15u);
  EXPECT_EQ(lit_ticks(out), range(7, 14));
  EXPECT_FALSE(out.back().laser);
  for (std::size_t i = 10; i < out.size(); ++i) {
    EXPECT_EQ(out[i].x_mm, 9.0f);
    EXPECT_EQ(out[i].y_mm, -9.0f);
  }
}

TEST(LaserDelayLine, FlushPlaysAPulseThatStartsAfterTheStream) {
  // on 6, off 9, the pulse [8,10) becomes [14,19): entirely after the last input tick.
  LaserDelayLine line(6, 9);
  const auto out = run(line, stream(10, {{8, 10}}), {10});
  EXPECT_EQ(lit_ticks(out), range(14, 19));
  EXPECT_FALSE(out.back().laser);
  EXPECT_EQ(out.size(), 20u);
}

// Against the rule stated in the header, evaluated on the whole stream at once.
TEST(LaserDelayLine, MatchesTheUnionOfShiftedPulsesOnRandomStreams) {
  std::mt19937 rng(42);
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 1 + static_cast<int>(rng() % 200);
    const int on = static_cast<int>(rng() % 12), off = static_cast<int>(rng() % 12);
    std::vector<ScanSample> in(static_cast<std::size_t>(n));
    bool lit = false;
    for (auto& s : in) {
      if (rng() % 4 == 0) lit = !lit;  // runs of random length
      s.laser = lit;
    }
    // Reference: pulses [a,b) (b = n if lit at the end) → union of [a+on, b+off).
    std::vector<bool> want(static_cast<std::size_t>(n + on + off + 2), false);
    for (int i = 0; i < n;) {
      if (!in[static_cast<std::size_t>(i)].laser) {
        ++i;
        continue;
      }
      int j = i;
      while (j < n && in[static_cast<std::size_t>(j)].laser) ++j;
      for (int t = i + on; t < j + off; ++t) want[static_cast<std::size_t>(t)] = true;
      i = j;
    }
    LaserDelayLine line(static_cast<std::size_t>(on), static_cast<std::size_t>(off));
    const auto out = run(line, in, {1 + rng() % 9, 1 + rng() % 30});
    for (std::size_t t = 0; t < want.size(); ++t) {
      const bool got = t < out.size() && out[t].laser;
      ASSERT_EQ(got, want[t]) << "trial " << trial << " tick " << t << " on " << on << " off " << off;
    }
    if (!out.empty()) {
      ASSERT_FALSE(out.back().laser);
    }
  }
}

}  // namespace
}  // namespace mark
