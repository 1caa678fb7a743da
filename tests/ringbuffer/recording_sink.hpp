#pragma once
// Test sink: keeps every sample and block size; can be told to fail at a given block.
#include <stdexcept>
#include <vector>

#include "ringbuffer/sink.hpp"

namespace mark::test {

template <class T>
class RecordingSink : public Sink<T> {
 public:
  void write(std::span<const T> block) override {
    if (halted) throw std::logic_error("write after halt");
    if (fail_at_block >= 0 && static_cast<long>(block_sizes.size()) == fail_at_block)
      throw std::runtime_error("device fault at block " + std::to_string(fail_at_block));
    samples.insert(samples.end(), block.begin(), block.end());
    block_sizes.push_back(block.size());
  }
  void halt() noexcept override { halted = true; }

  std::vector<T> samples;
  std::vector<std::size_t> block_sizes;
  bool halted = false;
  long fail_at_block = -1;
};

}  // namespace mark::test
