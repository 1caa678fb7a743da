#include "png_writer.hpp"

#include <png.h>

#include <stdexcept>

namespace mark::test {
namespace {

void append(png_structp png, png_bytep data, png_size_t n) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), n);
}

int channels(int colour_type) {
  switch (colour_type) {
    case PNG_COLOR_TYPE_RGB: return 3;
    case PNG_COLOR_TYPE_GRAY_ALPHA: return 2;
    case PNG_COLOR_TYPE_RGB_ALPHA: return 4;
    default: return 1;
  }
}

// CRC-32 as PNG chunks carry it (ISO 3309, bit-reversed polynomial 0xEDB88320).
std::uint32_t crc32(const std::string& bytes) {
  std::uint32_t c = 0xFFFFFFFFu;
  for (unsigned char b : bytes) {
    c ^= b;
    for (int k = 0; k < 8; ++k) c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
  }
  return c ^ 0xFFFFFFFFu;
}

std::string chunk(const char* type, const std::string& data) {
  std::string out;
  const auto be32 = [&](std::uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<char>((v >> s) & 0xFF));
  };
  be32(static_cast<std::uint32_t>(data.size()));
  const std::string body = std::string(type, 4) + data;
  out += body;
  be32(crc32(body));
  return out;
}

}  // namespace

std::string write_png(const PngSpec& spec) {
  std::string out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error("libpng could not write the test image");
  }
  png_set_write_fn(png, &out, append, nullptr);
  png_set_IHDR(png, info, spec.width, spec.height, spec.bit_depth, spec.colour_type,
               spec.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  std::vector<png_color> palette;
  for (std::size_t i = 0; i + 2 < spec.palette_rgb.size(); i += 3)
    palette.push_back({spec.palette_rgb[i], spec.palette_rgb[i + 1], spec.palette_rgb[i + 2]});
  if (!palette.empty()) png_set_PLTE(png, info, palette.data(), static_cast<int>(palette.size()));
  if (!spec.palette_alpha.empty())
    png_set_tRNS(png, info, spec.palette_alpha.data(), static_cast<int>(spec.palette_alpha.size()), nullptr);
  if (!spec.transparent_key.empty()) {
    png_color_16 key{};
    if (spec.transparent_key.size() == 1) {
      key.gray = static_cast<png_uint_16>(spec.transparent_key[0]);
    } else {
      key.red = static_cast<png_uint_16>(spec.transparent_key[0]);
      key.green = static_cast<png_uint_16>(spec.transparent_key[1]);
      key.blue = static_cast<png_uint_16>(spec.transparent_key[2]);
    }
    png_set_tRNS(png, info, nullptr, 0, &key);
  }
  png_write_info(png, info);
  // Rows packed by hand (depths below 8 several samples a byte, 16 big-endian), so the writer
  // needs no transforms.
  const int c = channels(spec.colour_type);
  const std::size_t bits = static_cast<std::size_t>(spec.width) * c * spec.bit_depth;
  std::vector<std::vector<png_byte>> rows(spec.height, std::vector<png_byte>((bits + 7) / 8));
  for (int y = 0; y < spec.height; ++y) {
    std::size_t bit = 0;
    for (int x = 0; x < spec.width; ++x)
      for (unsigned s : spec.pixel(x, y)) {
        if (spec.bit_depth == 16) {
          rows[y][bit / 8] = static_cast<png_byte>(s >> 8);
          rows[y][bit / 8 + 1] = static_cast<png_byte>(s & 0xFF);
        } else {
          rows[y][bit / 8] |= static_cast<png_byte>(s << (8 - spec.bit_depth - bit % 8));
        }
        bit += spec.bit_depth;
      }
  }
  std::vector<png_bytep> pointers;
  for (auto& r : rows) pointers.push_back(r.data());
  png_write_image(png, pointers.data());
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return out;
}

std::string png_header_only(std::uint32_t width, std::uint32_t height) {
  std::string ihdr;
  for (std::uint32_t v : {width, height})
    for (int s = 24; s >= 0; s -= 8) ihdr.push_back(static_cast<char>((v >> s) & 0xFF));
  ihdr += std::string("\x08\x00\x00\x00\x00", 5);  // 8-bit grey, deflate, adaptive filter, no interlace
  return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IEND", "");
}

}  // namespace mark::test
