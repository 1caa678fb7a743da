// PGM (Netpbm grey map): "P2" (ASCII samples) or "P5" (binary: one byte per sample when maxval
// < 256, else two, most significant first), header fields separated by whitespace, '#' comments
// to the end of the line. Every malformed or truncated input is an InputError with the byte
// offset, never a crash or an oversized allocation.
#include <cctype>
#include <cstdio>
#include <string>

#include "base/error.hpp"
#include "marker/image/gray_image.hpp"

namespace mark {
namespace {

class Reader {
 public:
  Reader(std::string_view b, const std::string& src) : b_(b), src_(src) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(src_ + ": PGM byte " + std::to_string(pos_) + ": " + what);
  }

  void skip_space_and_comments() {
    while (pos_ < b_.size()) {
      if (b_[pos_] == '#') {
        while (pos_ < b_.size() && b_[pos_] != '\n' && b_[pos_] != '\r') ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(b_[pos_]))) {
        ++pos_;
      } else {
        return;
      }
    }
  }

  // A non-negative decimal number of at most 9 digits.
  long number(const char* what) {
    skip_space_and_comments();
    if (pos_ >= b_.size()) fail(std::string("file ends before the ") + what);
    if (!std::isdigit(static_cast<unsigned char>(b_[pos_])))
      fail(std::string("expected the ") + what + " (a number), found '" + printable(b_[pos_]) + "'");
    long v = 0;
    int digits = 0;
    while (pos_ < b_.size() && std::isdigit(static_cast<unsigned char>(b_[pos_]))) {
      if (++digits > 9) fail(std::string("the ") + what + " is too large");
      v = v * 10 + (b_[pos_++] - '0');
    }
    return v;
  }

  std::size_t pos_ = 0;
  std::string_view b_;
  const std::string& src_;

 private:
  static std::string printable(char c) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7F) return std::string(1, c);
    char buf[8];
    std::snprintf(buf, sizeof buf, "\\x%02X", u);
    return buf;
  }
};

}  // namespace

GrayImage parse_pgm(std::string_view bytes, const std::string& source) {
  Reader r(bytes, source);
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '2' && bytes[1] != '5'))
    r.fail("not a PGM grey map (expected 'P2' or 'P5')");
  const bool binary = bytes[1] == '5';
  r.pos_ = 2;
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
    if (r.pos_ >= bytes.size() || !std::isspace(static_cast<unsigned char>(bytes[r.pos_])))
      r.fail("expected one whitespace byte before the samples");
    ++r.pos_;
    const std::size_t bps = maxval < 256 ? 1 : 2;
    if (bytes.size() - r.pos_ < n * bps)
      r.fail("truncated: " + std::to_string(n) + " samples of " + std::to_string(bps) +
             " byte(s) need " + std::to_string(n * bps) + " bytes, " +
             std::to_string(bytes.size() - r.pos_) + " left");
    img.pixels.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      long v = static_cast<unsigned char>(bytes[r.pos_ + k * bps]);
      if (bps == 2) v = v * 256 + static_cast<unsigned char>(bytes[r.pos_ + k * bps + 1]);
      if (v > maxval) {
        r.pos_ += k * bps;
        r.fail("sample " + std::to_string(v) + " exceeds the maximum value " + std::to_string(maxval));
      }
      img.pixels[k] = static_cast<float>(v) * scale;
    }
    return img;
  }
  // Every ASCII sample takes at least one digit: a header that promises more samples than the
  // file can hold is refused before anything is allocated for them.
  if (bytes.size() - r.pos_ < n)
    r.fail("truncated: " + std::to_string(n) + " ASCII samples need at least " + std::to_string(n) +
           " bytes, " + std::to_string(bytes.size() - r.pos_) + " left");
  img.pixels.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const long v = r.number("sample");
    if (v > maxval) r.fail("sample " + std::to_string(v) + " exceeds the maximum value " + std::to_string(maxval));
    img.pixels[k] = static_cast<float>(v) * scale;
  }
  return img;
}

}  // namespace mark
