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
//
// No allocation after construction (it runs on the drain thread): pending pulses live in a ring
// sized for the worst case. A pulse stays pending until its output ends, off_delay after its
// input ended; input pulses take at least two ticks each (on, then off), so at most
// off_delay / 2 + 1 finished pulses and one open pulse are pending at any tick.
#include <algorithm>
#include <cstddef>
#include <cstdint>
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
  // The flush tail is never longer than the longer delay plus the final off sample.
  std::size_t max_tail() const override { return std::max(on_delay_, off_delay_) + 2; }

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
  // Pending output pulses, ordered by start: a ring of fixed capacity.
  std::vector<Pulse> ring_;
  std::size_t head_ = 0, count_ = 0;
  Pulse& front() { return ring_[head_]; }
  Pulse& back() { return ring_[(head_ + count_ - 1) % ring_.size()]; }
  void push_back(Pulse p);
  void pop_front() { head_ = (head_ + 1) % ring_.size(), --count_; }
  void pop_back() { --count_; }
};

}  // namespace mark
