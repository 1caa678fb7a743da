#pragma once
// Where an image reader takes its bytes from: a file read as the decoder asks (never slurped
// whole, so a large file costs no more memory than the image it holds), or bytes already in
// memory (tests, the fuzz targets). Both know their size up front, so a header that promises more
// pixels than the file can hold is refused before anything is allocated for them.
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace mark {

class ImageSource {
 public:
  virtual ~ImageSource() = default;
  // Reads up to `n` bytes into `into`; fewer only at the end of the data.
  virtual std::size_t read(void* into, std::size_t n) = 0;
  // Back to the first byte; false if the data cannot be read again.
  virtual bool rewind() = 0;
  // Total bytes of the data.
  virtual std::uint64_t size() const = 0;
};

class MemoryImageSource final : public ImageSource {
 public:
  explicit MemoryImageSource(std::string_view bytes) : bytes_(bytes) {}
  std::size_t read(void* into, std::size_t n) override;
  bool rewind() override {
    pos_ = 0;
    return true;
  }
  std::uint64_t size() const override { return bytes_.size(); }

 private:
  std::string_view bytes_;
  std::size_t pos_ = 0;
};

class FileImageSource final : public ImageSource {
 public:
  // Throws InputError "'path': cannot open the image: <reason>" (also for a directory).
  explicit FileImageSource(const std::string& path);
  ~FileImageSource() override;
  FileImageSource(const FileImageSource&) = delete;
  FileImageSource& operator=(const FileImageSource&) = delete;
  std::size_t read(void* into, std::size_t n) override;
  bool rewind() override;
  std::uint64_t size() const override { return size_; }

 private:
  std::FILE* file_ = nullptr;
  std::uint64_t size_ = 0;
};

// Byte-at-a-time reading over a source, through a buffer: what a text header parser needs.
class ByteReader {
 public:
  explicit ByteReader(ImageSource& source) : source_(source) {}
  // The next byte without taking it, or -1 at the end.
  int peek() {
    if (at_ == end_ && !refill()) return -1;
    return buffer_[at_];
  }
  int get() {
    const int c = peek();
    if (c >= 0) ++at_, ++offset_;
    return c;
  }
  // Bulk read of up to `n` bytes (what is buffered first); returns how many.
  std::size_t read(unsigned char* into, std::size_t n);
  // Bytes taken so far: the position error messages name.
  std::uint64_t offset() const { return offset_; }
  std::uint64_t left() const { return source_.size() - offset_; }

 private:
  bool refill();
  ImageSource& source_;
  unsigned char buffer_[4096];
  std::size_t at_ = 0, end_ = 0;
  std::uint64_t offset_ = 0;
};

}  // namespace mark
