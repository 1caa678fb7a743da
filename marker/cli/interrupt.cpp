#include "marker/cli/interrupt.hpp"

#include <atomic>

namespace mark::cli {
namespace {

std::atomic<StopFlag*> g_flag{nullptr};
volatile std::sig_atomic_t g_signal = 0;
std::atomic<std::uint64_t> g_count{0};
static_assert(std::atomic<std::uint64_t>::is_always_lock_free, "a signal handler may only touch lock-free atomics");

extern "C" void on_signal(int sig) {
  g_signal = sig;
  g_count.fetch_add(1, std::memory_order_acq_rel);
  if (StopFlag* f = g_flag.load(std::memory_order_acquire)) f->request();
}

}  // namespace

InterruptScope::InterruptScope(StopFlag& flag) {
  g_signal = 0;
  g_flag.store(&flag, std::memory_order_release);
  struct sigaction sa{};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  sigaction(SIGINT, &sa, &old_int_);
  sigaction(SIGTERM, &sa, &old_term_);
}

InterruptScope::~InterruptScope() {
  sigaction(SIGINT, &old_int_, nullptr);
  sigaction(SIGTERM, &old_term_, nullptr);
  g_flag.store(nullptr, std::memory_order_release);
}

int InterruptScope::signal() const { return g_signal; }

std::uint64_t interrupt_count() { return g_count.load(std::memory_order_acquire); }

StopFlag& interrupt_flag() {
  static StopFlag flag;
  return flag;
}

}  // namespace mark::cli
