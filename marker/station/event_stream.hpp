#pragma once
// The station's events for the HTTP event stream (GET /api/events): one JSON line per state
// change and per part that ended, numbered, kept for readers that are a little behind. A reader
// waits for the next number without polling the station; close() wakes every reader at once
// (the server stopping): each gets what was published before, then the end.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <string>

namespace mark {

class EventStream {
 public:
  // The events a reader may still catch up on; one further behind loses the oldest (and is
  // told how many: next() skips to the oldest kept).
  static constexpr std::size_t kKept = 256;

  void publish(std::string data);
  void close();
  bool closed() const;
  // The number the next published event gets: a new reader starts here (only what follows).
  std::uint64_t end() const;
  // Event `seq` (or the oldest kept, if `seq` is gone): its data, `seq` advanced past it.
  // Nothing when `timeout` passed without one, or the stream closed and the reader has had
  // every event.
  std::optional<std::string> next(std::uint64_t& seq, std::chrono::milliseconds timeout);

 private:
  mutable std::mutex mutex_;
  std::condition_variable published_;
  std::deque<std::string> kept_;
  std::uint64_t first_ = 0;  // the number of kept_.front()
  bool closed_ = false;
};

}  // namespace mark
