// PGM (Netpbm grey map): "P2" (ASCII samples) or "P5" (binary: one byte per sample when maxval
// < 256, else two, most significant first), header fields separated by whitespace, '#' comments
// to the end of the line. Read as a stream: the header's size is checked against the limit and
// against what the file can hold before a sample is read, then samples go straight into the image
// (binary: one row at a time), so memory is the image itself. Every malformed or truncated input
// is an InputError with the byte offset, never a crash or an oversized allocation.
#include <cctype>
#include <cstdio>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "marker/image/gray_image.hpp"
#include "marker/image/image_source.hpp"

namespace mark {
namespace {

class HeaderReader {
 public:
  HeaderReader(ByteReader& in, const std::string& src) : in_(in), src_(src) {}

  [[noreturn]] void fail(const std::string& what) const { fail_at(in_.offset(), what); }
  [[noreturn]] void fail_at(std::uint64_t offset, const std::string& what) const {
    throw InputError(src_ + ": PGM byte " + std::to_string(offset) + ": " + what);
  }

  void skip_space_and_comments() {
    for (int c = in_.peek(); c >= 0; c = in_.peek()) {
      if (c == '#') {
        while (c >= 0 && c != '\n' && c != '\r') in_.get(), c = in_.peek();
      } else if (std::isspace(c)) {
        in_.get();
      } else {
        return;
      }
    }
  }

  // A non-negative decimal number of at most 9 digits.
  long number(const char* what) {
    skip_space_and_comments();
    const int first = in_.peek();
    if (first < 0) fail(std::string("file ends before the ") + what);
    if (!std::isdigit(first))
      fail(std::string("expected the ") + what + " (a number), found '" + printable(first) + "'");
    long v = 0;
    int digits = 0;
    for (int c = first; c >= 0 && std::isdigit(c); c = in_.peek()) {
      if (++digits > 9) fail(std::string("the ") + what + " is too large");
      v = v * 10 + (in_.get() - '0');
    }
    return v;
  }

 private:
  static std::string printable(int c) {
    if (c >= 0x20 && c < 0x7F) return std::string(1, static_cast<char>(c));
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02X", static_cast<unsigned>(c));
    return buf;
  }

  ByteReader& in_;
  const std::string& src_;
};

}  // namespace

GrayImage read_pgm(ImageSource& source, const std::string& name) {
  ByteReader in(source);
  HeaderReader r(in, name);
  const int p = in.get(), kind = in.get();
  if (p != 'P' || (kind != '2' && kind != '5')) r.fail_at(0, "not a PGM grey map (expected 'P2' or 'P5')");
  const bool binary = kind == '5';
  const long w = r.number("width"), h = r.number("height"), maxval = r.number("maximum value");
  if (w < 1 || h < 1) r.fail("width and height must be at least 1, got " + std::to_string(w) + "x" + std::to_string(h));
  if (static_cast<std::int64_t>(w) * h > kMaxImagePixels)
    r.fail("image of " + std::to_string(w) + "x" + std::to_string(h) + " pixels is larger than " +
           std::to_string(kMaxImagePixels) + " pixels");
  if (maxval < 1 || maxval > 65535) r.fail("maximum value must be 1..65535, got " + std::to_string(maxval));
  GrayImage img;
  img.width = static_cast<int>(w);
  img.height = static_cast<int>(h);
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  const float scale = 1.0f / static_cast<float>(maxval);
  if (binary) {
    // Exactly one whitespace byte separates the header from the samples.
    const int sep = in.peek();
    if (sep < 0 || !std::isspace(sep)) r.fail("expected one whitespace byte before the samples");
    in.get();
    const std::size_t bps = maxval < 256 ? 1 : 2;
    if (in.left() < n * bps)
      r.fail("truncated: " + std::to_string(n) + " samples of " + std::to_string(bps) + " byte(s) need " +
             std::to_string(n * bps) + " bytes, " + std::to_string(in.left()) + " left");
    img.pixels.resize(n);
    std::vector<unsigned char> row(static_cast<std::size_t>(w) * bps);
    for (long y = 0; y < h; ++y) {
      const std::uint64_t row_start = in.offset();
      if (in.read(row.data(), row.size()) != row.size()) r.fail("truncated: the file ended while it was read");
      for (long x = 0; x < w; ++x) {
        long v = row[x * bps];
        if (bps == 2) v = v * 256 + row[x * bps + 1];
        if (v > maxval)
          r.fail_at(row_start + x * bps,
                    "sample " + std::to_string(v) + " exceeds the maximum value " + std::to_string(maxval));
        img.pixels[static_cast<std::size_t>(y) * w + x] = static_cast<float>(v) * scale;
      }
    }
    return img;
  }
  // Every ASCII sample takes at least one digit: a header that promises more samples than the
  // file can hold is refused before anything is allocated for them.
  if (in.left() < n)
    r.fail("truncated: " + std::to_string(n) + " ASCII samples need at least " + std::to_string(n) + " bytes, " +
           std::to_string(in.left()) + " left");
  img.pixels.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const long v = r.number("sample");
    if (v > maxval) r.fail("sample " + std::to_string(v) + " exceeds the maximum value " + std::to_string(maxval));
    img.pixels[k] = static_cast<float>(v) * scale;
  }
  return img;
}

GrayImage parse_pgm(std::string_view bytes, const std::string& source) {
  MemoryImageSource memory(bytes);
  return read_pgm(memory, source);
}

}  // namespace mark
