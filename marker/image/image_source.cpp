#include "marker/image/image_source.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "base/error.hpp"

namespace mark {

std::size_t MemoryImageSource::read(void* into, std::size_t n) {
  const std::size_t k = std::min(n, bytes_.size() - pos_);
  std::memcpy(into, bytes_.data() + pos_, k);
  pos_ += k;
  return k;
}

FileImageSource::FileImageSource(const std::string& path) {
  const auto fail = [&](const std::string& why) { throw InputError("'" + path + "': cannot open the image: " + why); };
  file_ = std::fopen(path.c_str(), "rb");
  if (!file_) fail(std::strerror(errno));
  struct stat st {};
  const bool known = ::fstat(::fileno(file_), &st) == 0;
  if (!known || !S_ISREG(st.st_mode)) {
    const std::string why = !known ? std::strerror(errno) : S_ISDIR(st.st_mode) ? "it is a directory" : "not a regular file";
    std::fclose(file_);
    fail(why);
  }
  size_ = static_cast<std::uint64_t>(st.st_size);
}

FileImageSource::~FileImageSource() { std::fclose(file_); }

std::size_t FileImageSource::read(void* into, std::size_t n) { return std::fread(into, 1, n, file_); }

bool FileImageSource::rewind() { return std::fseek(file_, 0, SEEK_SET) == 0; }

bool ByteReader::refill() {
  at_ = 0;
  end_ = source_.read(buffer_, sizeof buffer_);
  return end_ > 0;
}

std::size_t ByteReader::read(unsigned char* into, std::size_t n) {
  std::size_t done = std::min(n, end_ - at_);
  std::memcpy(into, buffer_ + at_, done);
  at_ += done;
  if (done < n) done += source_.read(into + done, n - done);
  offset_ += done;
  return done;
}

}  // namespace mark
