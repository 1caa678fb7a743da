#include "tests/driver/lmc/usb/umockdev_board.hpp"

// <sys/ioctl.h> before <linux/usbdevice_fs.h>, or the _IOR macros are missing.
#include <sys/ioctl.h>
#include <linux/usbdevice_fs.h>

#include <cerrno>
#include <cstddef>
#include <cstring>
#include <stdexcept>

namespace mark::lmc::test {
namespace {

// 0x9588:0x9899, USB 2.0, one configuration, interface 0 (class 0xFF) with bulk EP 0x02 OUT and
// EP 0x88 IN of 512 bytes (usb_emulation.md §3).
constexpr const char* kDescriptors =
    "1201000200000040889599980001000000010902200001010080320904000002FF0000000705020200020007058802000200";

std::string device_text(int bus, int dev, const std::string& syspath) {
  char b[16], d[16];  // room for any int, so -Wformat-truncation holds at every -O
  std::snprintf(b, sizeof b, "%03d", bus);
  std::snprintf(d, sizeof d, "%03d", dev);
  return "P: " + syspath + "\n" +
         "N: bus/usb/" + b + "/" + d + "\n" +
         "E: SUBSYSTEM=usb\n"
         "E: DEVTYPE=usb_device\n"
         "E: DEVNAME=/dev/bus/usb/" + b + "/" + d + "\n" +
         "E: BUSNUM=" + b + "\n" +
         "E: DEVNUM=" + d + "\n" +
         "A: busnum=" + std::to_string(bus) + "\\n\n" +
         "A: devnum=" + std::to_string(dev) + "\\n\n" +
         "A: speed=480\\n\n"
         "A: bConfigurationValue=1\\n\n"
         "H: descriptors=" + kDescriptors + "\n";
}

usbdevfs_urb* urb_of(UMockdevIoctlData* d) { return reinterpret_cast<usbdevfs_urb*>(d->data); }

}  // namespace

Testbed::Testbed() : tb_(umockdev_testbed_new()) {}
Testbed::~Testbed() { g_object_unref(tb_); }

bool UmockdevBoard::available() {
  Testbed tb;
  return umockdev_in_mock_environment();
}

UmockdevBoard::UmockdevBoard(UMockdevTestbed* testbed, EmulatedBoard& board, int index)
    : testbed_(testbed), board_(board) {
  const int bus = 1, dev = 2 + index;
  syspath_ = "/devices/pci0000:00/0000:00:14.0/usb1/1-" + std::to_string(1 + index);
  char node[32];
  std::snprintf(node, sizeof node, "/dev/bus/usb/%03d/%03d", bus, dev);
  devnode_ = node;
  GError* err = nullptr;
  if (!umockdev_testbed_add_from_string(testbed_, device_text(bus, dev, syspath_).c_str(), &err)) {
    const std::string m = err ? err->message : "?";
    g_clear_error(&err);
    throw std::runtime_error("umockdev: cannot add the board: " + m);
  }
  // The testbed prefixes the sysfs path with /sys.
  syspath_ = "/sys" + syspath_;
  handler_ = umockdev_ioctl_base_new();
  g_signal_connect(handler_, "handle-ioctl", G_CALLBACK(&UmockdevBoard::on_ioctl), this);
  if (!umockdev_testbed_attach_ioctl(testbed_, devnode_.c_str(), handler_, &err)) {
    const std::string m = err ? err->message : "?";
    g_clear_error(&err);
    throw std::runtime_error("umockdev: cannot attach the ioctl handler: " + m);
  }
  board_.on_unplug = [this] { on_unplugged(); };
}

UmockdevBoard::~UmockdevBoard() {
  board_.on_unplug = nullptr;
  umockdev_testbed_detach_ioctl(testbed_, devnode_.c_str(), nullptr);
  std::lock_guard lock(mutex_);
  for (auto* q : {&pending_in_, &pending_out_, &reapable_})
    for (Urb& u : *q) {
      g_object_unref(u.buffer);
      g_object_unref(u.urb);
    }
  g_object_unref(handler_);
}

std::size_t UmockdevBoard::ioctls() const {
  std::lock_guard lock(mutex_);
  return ioctls_;
}

gboolean UmockdevBoard::on_ioctl(UMockdevIoctlBase*, UMockdevIoctlClient* client, gpointer self) {
  static_cast<UmockdevBoard*>(self)->handle(client);
  return TRUE;
}

void UmockdevBoard::on_unplugged() {
  // Unplugging: the kernel sends "remove"; libusb's monitor thread hears it. The ioctls fail
  // with ENODEV from now on (handle() asks the board).
  umockdev_testbed_uevent(testbed_, syspath_.c_str(), "remove");
}

void UmockdevBoard::finish(Urb u, int status, int actual) {
  urb_of(u.urb)->status = status;
  urb_of(u.urb)->actual_length = actual;
  reapable_.push_back(u);
}

void UmockdevBoard::serve_pending_ins() {
  while (!pending_in_.empty()) {
    std::array<std::uint8_t, kReplyBytes> reply{};
    const Urb u = pending_in_.front();
    const lmc::Urb r = board_.in(reply);
    if (r == lmc::Urb::pending) return;
    pending_in_.pop_front();
    if (r == lmc::Urb::done) {
      const int n = std::min<int>(urb_of(u.urb)->buffer_length, int(reply.size()));
      std::memcpy(u.buffer->data, reply.data(), std::size_t(n));
      finish(u, 0, n);
    } else {
      finish(u, r == lmc::Urb::stall ? -EPIPE : -ESHUTDOWN, 0);
    }
  }
}

void UmockdevBoard::submit(UMockdevIoctlClient* client, UMockdevIoctlData* arg) {
  GError* err = nullptr;
  Urb u;
  u.urb = umockdev_ioctl_data_resolve(arg, 0, sizeof(usbdevfs_urb), &err);
  if (!u.urb) {
    g_clear_error(&err);
    umockdev_ioctl_client_complete(client, -1, EFAULT);
    return;
  }
  const usbdevfs_urb* urb = urb_of(u.urb);
  u.buffer = umockdev_ioctl_data_resolve(u.urb, offsetof(usbdevfs_urb, buffer),
                                         std::size_t(urb->buffer_length), &err);
  if (!u.buffer) {
    g_clear_error(&err);
    g_object_unref(u.urb);
    umockdev_ioctl_client_complete(client, -1, EFAULT);
    return;
  }
  const bool in = (urb->endpoint & 0x80) != 0;
  lmc::Urb r;
  if (in) {
    pending_in_.push_back(u);
    serve_pending_ins();
    r = lmc::Urb::done;
  } else {
    r = board_.out(std::span<const std::uint8_t>(u.buffer->data, std::size_t(urb->buffer_length)));
    switch (r) {
      case lmc::Urb::done: finish(u, 0, urb->buffer_length); break;
      case lmc::Urb::stall: finish(u, -EPIPE, 0); break;
      case lmc::Urb::pending: pending_out_.push_back(u); break;
      case lmc::Urb::no_device: break;
    }
    serve_pending_ins();
  }
  if (r == lmc::Urb::no_device) {
    g_object_unref(u.buffer);
    g_object_unref(u.urb);
    umockdev_ioctl_client_complete(client, -1, ENODEV);
    return;
  }
  umockdev_ioctl_client_complete(client, 0, 0);
}

void UmockdevBoard::handle(UMockdevIoctlClient* client) {
  std::lock_guard lock(mutex_);
  ++ioctls_;
  const gulong req = umockdev_ioctl_client_get_request(client);
  UMockdevIoctlData* arg = umockdev_ioctl_client_get_arg(client);
  const bool gone = board_.unplugged();
  GError* err = nullptr;
  switch (req) {
    case USBDEVFS_GET_CAPABILITIES: {
      UMockdevIoctlData* d = umockdev_ioctl_data_resolve(arg, 0, sizeof(guint32), &err);
      if (!d) {
        g_clear_error(&err);
        umockdev_ioctl_client_complete(client, -1, EFAULT);
        return;
      }
      *reinterpret_cast<guint32*>(d->data) = USBDEVFS_CAP_BULK_CONTINUATION |
                                             USBDEVFS_CAP_NO_PACKET_SIZE_LIM |
                                             USBDEVFS_CAP_ZERO_PACKET | USBDEVFS_CAP_BULK_SCATTER_GATHER |
                                             USBDEVFS_CAP_REAP_AFTER_DISCONNECT;
      umockdev_ioctl_client_complete(client, 0, 0);
      g_object_unref(d);
      return;
    }
    case USBDEVFS_GETDRIVER:  // no kernel driver bound (libusb_kernel_driver_active → 0)
      umockdev_ioctl_client_complete(client, -1, gone ? ENODEV : ENODATA);
      return;
    case USBDEVFS_CLEAR_HALT:
      if (!gone) board_.clear_halt();
      umockdev_ioctl_client_complete(client, gone ? -1 : 0, gone ? ENODEV : 0);
      return;
    case USBDEVFS_CLAIMINTERFACE:
    case USBDEVFS_RELEASEINTERFACE:
    case USBDEVFS_SETINTERFACE:
    case USBDEVFS_SETCONFIGURATION:
    case USBDEVFS_RESET:
    case USBDEVFS_RESETEP:
      umockdev_ioctl_client_complete(client, gone ? -1 : 0, gone ? ENODEV : 0);
      return;
    case USBDEVFS_SUBMITURB:
      if (gone) {
        umockdev_ioctl_client_complete(client, -1, ENODEV);
        return;
      }
      submit(client, arg);
      return;
    case USBDEVFS_REAPURB:
    case USBDEVFS_REAPURBNDELAY: {
      serve_pending_ins();
      if (gone && reapable_.empty()) {
        // Hand back what was in flight as shut down, then report the device gone.
        for (auto* q : {&pending_in_, &pending_out_})
          while (!q->empty()) {
            finish(q->front(), -ESHUTDOWN, 0);
            q->pop_front();
          }
      }
      if (reapable_.empty()) {
        umockdev_ioctl_client_complete(client, -1, gone ? ENODEV : EAGAIN);
        return;
      }
      const Urb u = reapable_.front();
      reapable_.pop_front();
      UMockdevIoctlData* d = umockdev_ioctl_data_resolve(arg, 0, sizeof(void*), &err);
      if (!d) {
        g_clear_error(&err);
        umockdev_ioctl_client_complete(client, -1, EFAULT);
      } else {
        umockdev_ioctl_data_set_ptr(d, 0, u.urb);
        umockdev_ioctl_client_complete(client, 0, 0);
        g_object_unref(d);
      }
      g_object_unref(u.buffer);
      g_object_unref(u.urb);
      return;
    }
    case USBDEVFS_DISCARDURB: {
      const gulong addr = *reinterpret_cast<const gulong*>(arg->data);
      for (auto* q : {&pending_in_, &pending_out_})
        for (auto it = q->begin(); it != q->end(); ++it)
          if (it->urb->client_addr == addr) {
            finish(*it, -ENOENT, 0);
            q->erase(it);
            umockdev_ioctl_client_complete(client, 0, 0);
            return;
          }
      umockdev_ioctl_client_complete(client, -1, EINVAL);
      return;
    }
    default:
      umockdev_ioctl_client_complete(client, -1, ENOTTY);
      return;
  }
}

}  // namespace mark::lmc::test
