#include "marker/cli/interrupt.hpp"

#include <atomic>
#include <csignal>

namespace mark::cli {
namespace {

std::atomic<bool> g_requested{false};
struct sigaction g_old_int, g_old_term;

extern "C" void on_signal(int) { g_requested.store(true); }

}  // namespace

InterruptGuard::InterruptGuard() {
  g_requested = false;
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &g_old_int);
  sigaction(SIGTERM, &sa, &g_old_term);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &g_old_int, nullptr);
  sigaction(SIGTERM, &g_old_term, nullptr);
}

bool InterruptGuard::requested() { return g_requested.load(); }

}  // namespace mark::cli
