#include "marker/store/station_lock.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>

#include "marker/store/store_error.hpp"

namespace mark {
namespace {

// Above every byte SQLite locks (its lock page is at 1 GiB) and below off_t's limit.
constexpr std::uint64_t kBase = std::uint64_t{1} << 40;

std::uint64_t fnv1a(const std::string& s) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ULL;
  return h;
}

}  // namespace

StationLocks::StationLocks(const std::string& path, const std::string& name) : name_(name) {
  fd_ = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
  if (fd_ < 0)
    throw StoreError("serial store " + name + ": cannot open it for the station lock: " + std::strerror(errno),
                     StoreErrorKind::io);
}

StationLocks::~StationLocks() {
  if (fd_ >= 0) ::close(fd_);
}

bool StationLocks::claim(const std::string& station) {
  struct flock fl {};
  fl.l_type = F_WRLCK;
  fl.l_whence = SEEK_SET;
  fl.l_start = static_cast<off_t>(kBase + (fnv1a(station) & (kBase - 1)));
  fl.l_len = 1;
  fl.l_pid = 0;  // required for OFD locks
  if (::fcntl(fd_, F_OFD_SETLK, &fl) == 0) return true;
  if (errno == EAGAIN || errno == EACCES) return false;
  throw StoreError("serial store " + name_ + ": station lock: " + std::strerror(errno), StoreErrorKind::io);
}

}  // namespace mark
