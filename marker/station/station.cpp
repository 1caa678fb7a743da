#include "marker/station/station.hpp"

#include "base/error.hpp"

namespace mark {

std::string_view to_string(StationState state) {
  switch (state) {
    case StationState::idle: return "idle";
    case StationState::marking: return "marking";
    case StationState::paused: return "paused";
    case StationState::error: return "error";
  }
  return "?";
}

StationLights station_lights(StationState state, const std::optional<PartResult>& last) {
  StationLights l;
  l.ready = state == StationState::idle;
  l.busy = state == StationState::marking;
  l.done = !l.busy && last && last->good();
  l.error = state == StationState::error;
  return l;
}

namespace {
StationError busy() { return {"busy", "a part is being marked; try again when it ends (nothing queued)"}; }
}  // namespace

Station::Station(PartSource& source, std::function<void(const std::string&)> log)
    : source_(source), log_(std::move(log)) {
  counts_.job = source_.job();
}

Station::~Station() {
  if (async_.joinable()) async_.join();
}

void Station::emit(const std::string& line) const {
  if (log_) log_(line);
}

void Station::notify(const StationEvent& event) const {
  for (const auto& listener : listeners_) listener(event);
}

void Station::enter(StationState to) {
  state_ = to;
  emit("state " + std::string(to_string(to)));
  notify(StationEvent{to, std::nullopt});
}

void Station::add_listener(std::function<void(const StationEvent&)> listener) {
  std::lock_guard lock(mutex_);
  listeners_.push_back(std::move(listener));
}

void PartSource::read_log(const AuditFilter&, const std::function<bool(const AuditRow&)>&) {
  throw InputError("this station keeps no audit log");
}

std::string PartSource::preview_png() { throw InputError("this station draws no picture of its parts"); }

void Station::read_log(const AuditFilter& filter, const std::function<bool(const AuditRow&)>& row) {
  source_.read_log(filter, row);
}

// Everything but STATUS and ABORT uses the source, which a running part holds: refused busy.
// Paused and error refuse only what would mark; the others apply.
std::optional<StationError> Station::refuse_unless_still() const {
  if (state_ == StationState::marking) return busy();
  return std::nullopt;
}

std::optional<StationError> Station::begin() {
  switch (state_) {
    case StationState::marking: return busy();
    case StationState::paused: return StationError{"paused", "the station is paused: RESUME first"};
    case StationState::error:
      return StationError{"error", "the station is in error (" + counts_.error + "): RESET first"};
    case StationState::idle: break;
  }
  if (async_.joinable()) async_.join();  // the last asynchronous part ended (state idle)
  stop_.reset();  // an ABORT from now on stops this part
  enter(StationState::marking);
  return std::nullopt;
}

MarkAttempt Station::mark() {
  {
    std::lock_guard lock(mutex_);
    if (auto e = begin()) return {std::nullopt, e};
  }
  return run();
}

std::optional<StationError> Station::mark_async() {
  std::lock_guard lock(mutex_);
  if (auto e = begin()) return e;
  async_ = std::thread([this] { run(); });
  return std::nullopt;
}

MarkAttempt Station::run() {
  MarkAttempt a;
  std::string failure;
  bool refused = false;
  try {
    a.part = source_.mark_next(stop_);
  } catch (const InputError& e) {
    // Refused before anything was consumed (a glyph missing, a counter stopped): no part.
    refused = true;
    a.error = StationError{"refused", e.what()};
  } catch (const std::exception& e) {
    // The device could not start: PartRunner recorded the part failed before throwing.
    failure = e.what();
    a.error = StationError{"failed", failure};
  }
  std::lock_guard lock(mutex_);
  if (a.part) {
    const PartResult& part = *a.part;
    ++counts_.parts;
    ++counts_.outcomes[std::string(part.outcome_name())];
    counts_.last = part;
    emit("part " + std::to_string(part.mark_id) + " " + std::string(part.outcome_name()) +
         (part.message.empty() ? "" : ": " + part.message));
    if (part.outcome == JobOutcome::failed) failure = part.message.empty() ? "the part failed" : part.message;
  } else if (refused) {
    emit("mark refused: " + a.error->message);
  }
  if (a.part) notify(StationEvent{failure.empty() ? StationState::idle : StationState::error, a.part});
  if (!failure.empty()) {
    counts_.error = failure;
    state_ = StationState::error;
    emit("state error: " + failure);
    notify(StationEvent{StationState::error, std::nullopt});
  } else {
    enter(StationState::idle);
  }
  ended_.notify_all();
  return a;
}

StationState Station::abort() {
  // The flag first: a part between begin() and the device's begin_job sees it in the drain.
  stop_.request();
  source_.abort_device();
  std::lock_guard lock(mutex_);
  emit(std::string("abort (state ") + std::string(to_string(state_)) + "): laser off");
  return state_;
}

std::optional<StationError> Station::pause() { return hold(StationState::paused); }
std::optional<StationError> Station::resume() { return hold(StationState::idle); }

// PAUSE and RESUME: between idle and paused only; a part or a fault must end first.
std::optional<StationError> Station::hold(StationState to) {
  std::lock_guard lock(mutex_);
  if (state_ == StationState::marking) return busy();
  if (state_ == StationState::error) return StationError{"error", "the station is in error: RESET first"};
  if (state_ != to) enter(to);
  return std::nullopt;
}

std::optional<StationError> Station::reset() {
  std::lock_guard lock(mutex_);
  if (state_ == StationState::marking) return busy();
  try {
    source_.reset_device();
  } catch (const std::exception& e) {
    return StationError{"error", std::string("the device did not reset: ") + e.what()};
  }
  if (state_ == StationState::error) {
    counts_.error.clear();
    emit("reset");
    enter(StationState::idle);
  }
  return std::nullopt;
}

std::optional<StationError> Station::set_variable(const std::string& name, const std::string& value) {
  std::lock_guard lock(mutex_);
  if (auto e = refuse_unless_still()) return e;
  try {
    source_.set_variable(name, value);
  } catch (const std::exception& e) {
    return StationError{"refused", e.what()};
  }
  emit("set " + name);
  return std::nullopt;
}

std::optional<StationError> Station::load(const std::string& job) {
  std::lock_guard lock(mutex_);
  if (auto e = refuse_unless_still()) return e;
  try {
    source_.load(job);
  } catch (const std::exception& e) {
    return StationError{"refused", e.what()};
  }
  counts_.job = source_.job();
  emit("loaded " + counts_.job);
  return std::nullopt;
}

std::optional<StationError> Station::preview(std::vector<ObjectText>& texts,
                                             std::map<std::string, std::int64_t>& serials) {
  std::lock_guard lock(mutex_);
  if (auto e = refuse_unless_still()) return e;
  try {
    texts = source_.preview(&serials);
  } catch (const std::exception& e) {
    return StationError{"refused", e.what()};
  }
  return std::nullopt;
}

std::optional<StationError> Station::preview_png(std::string& png) {
  std::lock_guard lock(mutex_);
  if (auto e = refuse_unless_still()) return e;
  try {
    png = source_.preview_png();
  } catch (const std::exception& e) {
    return StationError{"refused", e.what()};
  }
  return std::nullopt;
}

std::optional<StationError> Station::next_serial(const std::string& counter,
                                                 std::optional<std::int64_t>& next) {
  std::lock_guard lock(mutex_);
  if (auto e = refuse_unless_still()) return e;
  try {
    next = source_.next_serial(counter);
  } catch (const std::exception& e) {
    return StationError{"notfound", e.what()};
  }
  return std::nullopt;
}

StationStatus Station::status() const {
  std::lock_guard lock(mutex_);
  StationStatus s = counts_;
  s.state = state_;
  return s;
}

void Station::wait_idle() {
  std::unique_lock lock(mutex_);
  ended_.wait(lock, [this] { return state_ != StationState::marking; });
  lock.unlock();
}

}  // namespace mark
