#include "marker/output/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>

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

// Where standard output was while a file has it (claim_standard_output); -1 when no file has it.
int file_stdout = -1;

// Why a file that exists at `target` cannot be replaced by a regular one, or "" when it can.
std::string not_replaceable(const std::string& target) {
  struct stat st {};
  if (::stat(target.c_str(), &st) != 0 || S_ISREG(st.st_mode)) return {};
  if (S_ISDIR(st.st_mode)) return "is a directory";
  const char* what = S_ISFIFO(st.st_mode) ? "a named pipe (FIFO)" : S_ISSOCK(st.st_mode) ? "a socket" : "a device";
  return std::string("is ") + what + ", not a regular file: give a file name, or - for standard output";
}

void write_all(int fd, std::string_view bytes, const std::function<void(int)>& on_error) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      on_error(errno);
      return;
    }
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

std::string output_format(const std::string& path, std::initializer_list<std::string_view> extensions) {
  if (is_standard_output(path) && extensions.size() > 0) return std::string(*extensions.begin());
  return lower_extension(path);
}

std::string write_target(const std::string& path) {
  fs::path p(path);
  // 40 links, as the kernel follows before it says ELOOP.
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p.string();
    std::error_code error;
    const fs::path target = fs::read_symlink(p, error);
    if (error) throw InputError("output file '" + path + "': cannot read the link: " + error.message());
    p = target.is_absolute() ? target : p.parent_path() / target;
  }
  throw InputError("output file '" + path + "': too many levels of symbolic links");
}

void claim_standard_output() {
  if (file_stdout >= 0) return;
  std::cout.flush();
  std::fflush(stdout);
  file_stdout = ::fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 3);
  if (file_stdout < 0) throw InputError("standard output: " + system_reason(errno));
  ::dup2(STDERR_FILENO, STDOUT_FILENO);
}

void release_standard_output() {
  if (file_stdout < 0) return;
  std::cout.flush();
  std::fflush(stdout);
  ::dup2(file_stdout, STDOUT_FILENO);
  ::close(file_stdout);
  file_stdout = -1;
}

void check_output_path(std::string_view option, const std::string& path,
                       std::initializer_list<std::string_view> extensions) {
  const std::string who = std::string(option) + " '" + path + "'";
  if (path.empty()) throw InputError(std::string(option) + ": the file name is empty");
  if (is_standard_output(path)) {
    claim_standard_output();
    return;
  }
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
  const std::string target = write_target(path);
  if (const std::string why = not_replaceable(target); !why.empty()) throw InputError(who + ": " + why);
  struct stat st {};
  const std::string dir = directory_of(target);
  if (::stat(dir.c_str(), &st) != 0)
    throw InputError(who + ": directory '" + dir + "': " + system_reason(errno));
  if (!S_ISDIR(st.st_mode)) throw InputError(who + ": '" + dir + "' is not a directory");
  // Access rules, read-only mounts and special file systems only show when a file is created.
  std::string probe;
  const int fd = open_temporary(target, probe);
  if (fd < 0) throw InputError(who + ": cannot create a file in '" + dir + "': " + system_reason(errno));
  ::close(fd);
  ::unlink(probe.c_str());
}

void write_file_whole(const std::string& path, std::string_view bytes) {
  if (is_standard_output(path)) {
    write_all(file_stdout >= 0 ? file_stdout : STDOUT_FILENO, bytes, [](int error) {
      throw InputError("standard output: cannot write: " + system_reason(error));
    });
    return;
  }
  // Through a link to its target; never over a device, a FIFO or a socket.
  const std::string target = write_target(path);
  if (const std::string why = not_replaceable(target); !why.empty()) fail(path, why);
  std::string temp;
  const int fd = open_temporary(target, temp);
  if (fd < 0) fail(path, "cannot create a file in '" + directory_of(target) + "': " + system_reason(errno));
  auto abandon = [&](int error, const std::string& what) {
    ::close(fd);
    ::unlink(temp.c_str());
    fail(path, what + ": " + system_reason(error));
  };
  write_all(fd, bytes, [&](int error) { abandon(error, "cannot write"); });
  // On disk before the rename, so a crash leaves the old file or the new one, never a torn one.
  if (::fsync(fd) != 0) abandon(errno, "cannot write");
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(temp.c_str());
    fail(path, "cannot write: " + system_reason(error));
  }
  if (::rename(temp.c_str(), target.c_str()) != 0) {
    const int error = errno;
    ::unlink(temp.c_str());
    fail(path, "cannot replace it: " + system_reason(error));
  }
}

}  // namespace mark
