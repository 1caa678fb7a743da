#include "marker/station/event_stream.hpp"

namespace mark {

void EventStream::publish(std::string data) {
  {
    std::lock_guard lock(mutex_);
    if (closed_) return;
    kept_.push_back(std::move(data));
    if (kept_.size() > kKept) {
      kept_.pop_front();
      ++first_;
    }
  }
  published_.notify_all();
}

void EventStream::close() {
  {
    std::lock_guard lock(mutex_);
    closed_ = true;
  }
  published_.notify_all();
}

bool EventStream::closed() const {
  std::lock_guard lock(mutex_);
  return closed_;
}

std::uint64_t EventStream::end() const {
  std::lock_guard lock(mutex_);
  return first_ + kept_.size();
}

std::optional<std::string> EventStream::next(std::uint64_t& seq, std::chrono::milliseconds timeout) {
  std::unique_lock lock(mutex_);
  published_.wait_for(lock, timeout, [&] { return closed_ || seq < first_ + kept_.size(); });
  // Closed: what was published before still goes out (the part a stopping station aborted).
  if (seq >= first_ + kept_.size()) return std::nullopt;
  if (seq < first_) seq = first_;
  return kept_[static_cast<std::size_t>(seq++ - first_)];
}

}  // namespace mark
