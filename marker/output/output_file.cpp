#include "marker/output/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "base/error.hpp"

namespace mark {
namespace {

namespace fs = std::filesystem;

std::string directory_of(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? "." : parent.string();
}

std::string system_reason(int error) { return std::strerror(error); }

// A file of our own next to `path`, created exclusively with the usual permissions (0666 less the
// umask, as any other new file gets). Returns its descriptor and name; -1 and errno on failure.
int open_temporary(const std::string& path, std::string& name) {
  static std::atomic<unsigned> counter{0};
  const fs::path p(path);
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::string file = ".";
    file += p.filename().string();
    file += '.';
    file += std::to_string(getpid());
    file += '.';
    file += std::to_string(counter++);
    file += ".part";
    const fs::path temp = p.parent_path() / file;
    name = temp.string();
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  errno = EEXIST;
  return -1;
}

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
  throw InputError("output file '" + path + "': " + reason);
}

}  // namespace

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void check_output_path(std::string_view option, const std::string& path,
                       std::initializer_list<std::string_view> extensions) {
  const std::string who = std::string(option) + " '" + path + "'";
  if (path.empty()) throw InputError(std::string(option) + ": the file name is empty");
  if (extensions.size() > 0) {
    const std::string ext = lower_extension(path);
    if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end()) {
      std::string allowed;
      std::size_t k = 0;
      for (std::string_view e : extensions)
        allowed += (k++ == 0 ? "" : k == extensions.size() ? " or " : ", ") + std::string(e);
      throw InputError(who + ": the name must end in " + allowed);
    }
  }
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) throw InputError(who + ": is a directory");
  const std::string dir = directory_of(path);
  if (::stat(dir.c_str(), &st) != 0)
    throw InputError(who + ": directory '" + dir + "': " + system_reason(errno));
  if (!S_ISDIR(st.st_mode)) throw InputError(who + ": '" + dir + "' is not a directory");
  // Access rules, read-only mounts and special file systems only show when a file is created.
  std::string probe;
  const int fd = open_temporary(path, probe);
  if (fd < 0) throw InputError(who + ": cannot create a file in '" + dir + "': " + system_reason(errno));
  ::close(fd);
  ::unlink(probe.c_str());
}

void write_file_whole(const std::string& path, std::string_view bytes) {
  std::string temp;
  const int fd = open_temporary(path, temp);
  if (fd < 0) fail(path, "cannot create a file in '" + directory_of(path) + "': " + system_reason(errno));
  auto abandon = [&](int error, const std::string& what) {
    ::close(fd);
    ::unlink(temp.c_str());
    fail(path, what + ": " + system_reason(error));
  };
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      abandon(errno, "cannot write");
    }
    done += static_cast<std::size_t>(n);
  }
  // On disk before the rename, so a crash leaves the old file or the new one, never a torn one.
  if (::fsync(fd) != 0) abandon(errno, "cannot write");
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(temp.c_str());
    fail(path, "cannot write: " + system_reason(error));
  }
  if (::rename(temp.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(temp.c_str());
    fail(path, "cannot replace it: " + system_reason(error));
  }
}

}  // namespace mark
