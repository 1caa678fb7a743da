#pragma once
// The emulated LMC board behind real usbfs ioctls (usb_emulation.md, style (b)): a umockdev
// testbed with a 0x9588:0x9899 device whose ioctls a dynamic handler serves from an
// EmulatedBoard, so the driver's real libusb calls (open, claim, bulk transfers, timeouts via
// DISCARDURB, clear-halt) cross the real Linux backend. The process must run under
// umockdev-wrapper (LD_PRELOAD of umockdev's preload library); available() says whether it does.
//
// The handler runs on umockdev's worker thread; URBs the board leaves pending (an IN before its
// reply, a hung board) wait in lists until the board answers or libusb discards them.
#include <glib-object.h>
#include <umockdev.h>

#include <deque>
#include <mutex>
#include <string>

#include "driver/lmc/emulated_board.hpp"

namespace mark::lmc::test {

class UmockdevBoard {
 public:
  // Whether this process runs in a umockdev environment (creates and drops a testbed).
  static bool available();

  // Adds board number `index` (bus 1, device 2 + index) to `testbed` and serves its ioctls
  // from `board`.
  UmockdevBoard(UMockdevTestbed* testbed, EmulatedBoard& board, int index = 0);
  ~UmockdevBoard();
  UmockdevBoard(const UmockdevBoard&) = delete;
  UmockdevBoard& operator=(const UmockdevBoard&) = delete;

  const std::string& devnode() const { return devnode_; }
  std::size_t ioctls() const;  // served so far

 private:
  struct Urb {
    UMockdevIoctlData* urb = nullptr;
    UMockdevIoctlData* buffer = nullptr;
  };
  static gboolean on_ioctl(UMockdevIoctlBase* base, UMockdevIoctlClient* client, gpointer self);
  void handle(UMockdevIoctlClient* client);
  void submit(UMockdevIoctlClient* client, UMockdevIoctlData* arg);
  void finish(Urb u, int status, int actual);
  void serve_pending_ins();
  void on_unplugged();

  UMockdevTestbed* testbed_;
  EmulatedBoard& board_;
  UMockdevIoctlBase* handler_ = nullptr;
  std::string syspath_, devnode_;
  mutable std::mutex mutex_;
  std::deque<Urb> pending_in_, pending_out_, reapable_;
  std::size_t ioctls_ = 0;
};

// One testbed for a test: created before libusb_init, as the recipe requires.
class Testbed {
 public:
  Testbed();
  ~Testbed();
  UMockdevTestbed* get() const { return tb_; }

 private:
  UMockdevTestbed* tb_;
};

}  // namespace mark::lmc::test
