#include "ringbuffer/laser_delay_line.hpp"

#include <stdexcept>

namespace mark {

LaserDelayLine::LaserDelayLine(std::size_t on_delay_ticks, std::size_t off_delay_ticks)
    : on_delay_(on_delay_ticks), off_delay_(off_delay_ticks), ring_(off_delay_ticks / 2 + 3) {}

void LaserDelayLine::push_back(Pulse p) {
  // Cannot happen by the bound in the header; refuse loudly rather than overwrite a pulse.
  if (count_ == ring_.size()) throw std::logic_error("laser delay line: pulse ring overflow");
  ring_[(head_ + count_) % ring_.size()] = p;
  ++count_;
}

void LaserDelayLine::feed(bool laser_in) {
  if (laser_in && !input_on_) {
    push_back({now_ + on_delay_, open_end});
  } else if (!laser_in && input_on_) {
    Pulse& p = back();  // the pulse this off edge ends is the newest one
    p.end = now_ + off_delay_;
    if (p.end <= p.start) pop_back();  // shorter than on_delay − off_delay: dropped
  }
  input_on_ = laser_in;
}

bool LaserDelayLine::output_bit() {
  // Pulses are ordered by start; a finished front pulse can go. Only the front can cover now_:
  // a later pulse starts no earlier, and the front has not ended yet.
  while (count_ > 0 && front().end <= now_) pop_front();
  return count_ > 0 && front().start <= now_;
}

void LaserDelayLine::apply(std::span<ScanSample> block) {
  for (ScanSample& s : block) {
    feed(s.laser);
    s.laser = last_out_ = output_bit();
    ++now_;
  }
}

void LaserDelayLine::flush(const ScanSample& last, std::vector<ScanSample>& tail) {
  feed(false);  // the end of the stream is an off edge
  // Emit hold samples until every pending pulse has been played and the laser is off; the last
  // sample owed is the one that switches it off, so the device is left dark.
  if (last_out_ || count_ > 0) {
    ScanSample s = last;
    do {
      s.laser = last_out_ = output_bit();
      tail.push_back(s);
      ++now_;
    } while (s.laser || count_ > 0);
  }
  now_ = 0;
  input_on_ = false;
  last_out_ = false;
  head_ = count_ = 0;
}

}  // namespace mark
