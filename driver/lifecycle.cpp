#include "driver/lifecycle.hpp"

namespace mark {
namespace {

bool final_state(DeviceState s) {
  return s == DeviceState::done || s == DeviceState::aborted || s == DeviceState::failed;
}

}  // namespace

Lifecycle::Lifecycle(std::string device) : device_(std::move(device)) {}

void Lifecycle::refuse(std::string_view call, DeviceState state, std::string_view why) const {
  throw DeviceStateError(device_, std::string(call), state, why);
}

void Lifecycle::refuse(std::string_view call, std::string_view why) const {
  refuse(call, state(), why);
}

void Lifecycle::require(DeviceState want, std::string_view call, std::string_view why) const {
  const DeviceState s = state();
  if (s != want) refuse(call, s, why);
}

void Lifecycle::begin(std::string_view call) {
  DeviceState s = DeviceState::idle;
  // One exchange: an abort() racing in turns idle into aborted first, and then this refuses.
  if (!state_.compare_exchange_strong(s, DeviceState::running, std::memory_order_acq_rel))
    refuse(call, s,
           s == DeviceState::running ? "a job is running: end_job() or abort() it first"
                                     : "the last job has ended: reset() the device first");
  halted_.store(false, std::memory_order_release);  // a halt belongs to the job it stopped
}

DeviceState Lifecycle::end(std::string_view call) {
  DeviceState s = state();
  if (s == DeviceState::idle) refuse(call, s, "no job was begun");
  if (s != DeviceState::running) return s;  // ended already: aborted, failed (or done twice)
  const DeviceState to = halted_.load(std::memory_order_acquire) || abort_requested()
                             ? DeviceState::aborted
                             : DeviceState::done;
  // An abort() between the load and here wins: the exchange fails and s holds `aborted`.
  return state_.compare_exchange_strong(s, to, std::memory_order_acq_rel) ? to : s;
}

void Lifecycle::leave() {
  DeviceState s = DeviceState::running;
  state_.compare_exchange_strong(s, DeviceState::idle, std::memory_order_acq_rel);
}

void Lifecycle::reset(std::string_view call) {
  std::lock_guard lock(fault_mutex_);
  DeviceState s = state();
  if (s == DeviceState::running) refuse(call, s, "abort() or end_job() the job first");
  if (!final_state(s)) return;
  fault_.reset();
  halted_.store(false, std::memory_order_release);
  abort_.store(false, std::memory_order_release);
  // Only abort() changes the state besides the owner, and it leaves a final state alone, so
  // this exchange does not fail.
  state_.compare_exchange_strong(s, DeviceState::idle, std::memory_order_acq_rel);
  // An abort() that raised its request after the clearing above but found the final state
  // still in place did nothing to the state: honour it now, so an idle device never carries a
  // pending abort into its next job.
  if (abort_requested()) {
    DeviceState idle = DeviceState::idle;
    state_.compare_exchange_strong(idle, DeviceState::aborted, std::memory_order_acq_rel);
  }
}

void Lifecycle::abort() noexcept {
  abort_.store(true, std::memory_order_release);
  DeviceState s = state_.load(std::memory_order_acquire);
  while (s == DeviceState::idle || s == DeviceState::running)
    if (state_.compare_exchange_weak(s, DeviceState::aborted, std::memory_order_acq_rel)) break;
}

const DeviceFault& Lifecycle::fail(const DeviceFault& fault) {
  std::lock_guard lock(fault_mutex_);
  DeviceState s = state();
  while (s == DeviceState::idle || s == DeviceState::running) {
    if (state_.compare_exchange_weak(s, DeviceState::failed, std::memory_order_acq_rel)) {
      fault_ = fault;
      break;
    }
  }
  return fault;
}

std::optional<DeviceFault> Lifecycle::fault() const {
  std::lock_guard lock(fault_mutex_);
  return fault_;
}

DeviceStatus Lifecycle::snapshot() const {
  DeviceStatus st;
  std::lock_guard lock(fault_mutex_);
  st.state = state();
  st.fault = fault_;
  return st;
}

}  // namespace mark
