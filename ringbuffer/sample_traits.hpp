#pragma once
// Customisation point for what the drain emits while it has nothing to emit (an underrun): a
// sample that holds the last position with the output power off. The default for a sample type
// without a laser bit repeats the last sample; ScanSample switches the laser off
// (ringbuffer/scan_sample.hpp). Found by argument-dependent lookup, so a sample type declares
// its own `T hold_sample(const T& last)` next to itself.

namespace mark {

template <class T>
T hold_sample(const T& last) {
  return last;
}

}  // namespace mark
