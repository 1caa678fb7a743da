#pragma once
// A streaming transform the drain applies to every block it pops, between the line memory and
// the device (the seed's delay means sit exactly there). State carries across blocks.
#include <cstddef>
#include <span>
#include <vector>

namespace mark {

template <class T>
class SampleFilter {
 public:
  virtual ~SampleFilter() = default;

  // Transform one block in place; the block follows the previous one in the stream.
  virtual void apply(std::span<T> block) = 0;

  // End of stream: append to `tail` the samples still owed (e.g. the hold samples that carry a
  // pending delayed laser-off), given the last sample of the stream. Leaves the filter reset.
  virtual void flush(const T& last, std::vector<T>& tail) = 0;

  // The most samples flush() ever appends, so the drain can reserve the tail before the job
  // (its thread never allocates).
  virtual std::size_t max_tail() const { return 0; }
};

}  // namespace mark
