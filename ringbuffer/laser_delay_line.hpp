#pragma once
// The seed's delay means: the laser on/off bit leaves the drain delayed against the coordinates
// by the scanner's response time, so the beam switches where the mirrors actually are. Laser-on
// edges are delayed by on_delay ticks and laser-off edges by off_delay ticks, independently;
// coordinates and power are never changed or moved.
//
// Rule (the same one a pair of RTC-style laser delays implies): every input pulse — laser on
// from tick a up to, not including, tick b — becomes the output pulse [a + on_delay,
// b + off_delay). A pulse that becomes empty (shorter than on_delay − off_delay) is dropped, so
// a late on edge can never switch the laser on after its own off edge; output pulses that
// overlap (a gap shorter than off_delay − on_delay) merge into one, the laser staying on. The
// output laser bit at a tick is on exactly when that tick lies inside some output pulse.
//
// flush(): the stream end counts as a laser-off edge; the filter emits hold samples at the last
// position until every pending output pulse has been played, ending with a laser-off sample, so
// the device is left dark (nothing is emitted if the output is already off with nothing pending).
#include <cstddef>
#include <cstdint>
#include <deque>
#include <span>
#include <vector>

#include "ringbuffer/sample_filter.hpp"
#include "ringbuffer/scan_sample.hpp"

namespace mark {

class LaserDelayLine : public SampleFilter<ScanSample> {
 public:
  LaserDelayLine(std::size_t on_delay_ticks, std::size_t off_delay_ticks);

  void apply(std::span<ScanSample> block) override;
  void flush(const ScanSample& last, std::vector<ScanSample>& tail) override;

  std::size_t on_delay_ticks() const { return on_delay_; }
  std::size_t off_delay_ticks() const { return off_delay_; }

 private:
  // An output pulse [start, end) in stream ticks; end is open while the input is still on.
  struct Pulse {
    std::uint64_t start;
    std::uint64_t end;
  };
  static constexpr std::uint64_t open_end = UINT64_MAX;

  void feed(bool laser_in);   // register the input bit of tick now_
  bool output_bit();          // the output bit of tick now_ (drops finished pulses)

  std::size_t on_delay_;
  std::size_t off_delay_;
  std::uint64_t now_ = 0;     // stream tick of the next sample
  bool input_on_ = false;     // input laser bit of the previous tick
  bool last_out_ = false;     // output laser bit of the previous tick
  std::deque<Pulse> pulses_;  // pending output pulses, ordered by start
};

}  // namespace mark
