#pragma once
// Producer-side batching for a line memory: a generator that makes one sample at a time appends
// it here, and the writer hands the memory whole batches. LineMemory::push(const T&) touches the
// queue's shared indices on every call (~15 M samples/s between two cores); batches of 256 go
// at well over 100 M/s. Staged samples are not visible to the drain until the batch fills or
// flush()/close() is called — call flush() whenever the producer is about to pause, or the
// drain may underrun while samples sit here.
#include <cstddef>
#include <vector>

#include "ringbuffer/line_memory.hpp"

namespace mark {

template <class T>
class LineWriter {
 public:
  explicit LineWriter(LineMemory<T>& memory, std::size_t batch = 256)
      : memory_(memory), staged_(batch ? batch : 1), data_(staged_.data()), capacity_(staged_.size()) {}
  LineWriter(const LineWriter&) = delete;
  LineWriter& operator=(const LineWriter&) = delete;
  // Hands over what is staged (no-op once the memory is aborted).
  ~LineWriter() { flush(); }

  // Append one sample. Returns false when a batch handed over found the memory aborted (stop
  // producing then); between hand-overs it returns true without looking.
  bool push(const T& sample) {
    data_[count_] = sample;
    return ++count_ < capacity_ ? true : flush();
  }

  // Hand the staged samples to the memory now, waiting while it is full. False if aborted.
  bool flush() {
    const bool ok = memory_.push(std::span<const T>(data_, count_));
    count_ = 0;
    return ok;
  }

  // Flush and close the memory: the end of the job.
  bool close() {
    const bool ok = flush();
    memory_.close();
    return ok;
  }

  std::size_t staged() const { return count_; }

 private:
  LineMemory<T>& memory_;
  std::vector<T> staged_;
  T* data_;
  std::size_t capacity_;
  std::size_t count_ = 0;
};

}  // namespace mark
