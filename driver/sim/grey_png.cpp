#include "driver/sim/grey_png.hpp"

#include <png.h>

#include <cmath>
#include <stdexcept>

namespace mark {
namespace {

[[noreturn]] void fail(const std::string& why) { throw std::runtime_error("cannot encode the PNG: " + why); }

// libpng reports errors by longjmp; the handler turns them into a message we throw after.
void on_png_error(png_structp png, png_const_charp message) {
  auto* text = static_cast<std::string*>(png_get_error_ptr(png));
  *text = message ? message : "libpng error";
  png_longjmp(png, 1);
}
void on_png_warning(png_structp, png_const_charp) {}

void append_bytes(png_structp png, png_bytep data, png_size_t length) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), length);
}
void flush_nothing(png_structp) {}

// The encoding itself, kept free of C++ objects with destructors: longjmp must not skip them.
bool encode(std::string* out, const GreyImage& img, std::string* error) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, error, on_png_error, on_png_warning);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, info ? &info : nullptr);
    return false;
  }
  png_set_write_fn(png, out, append_bytes, flush_nothing);
  png_set_IHDR(png, info, static_cast<png_uint_32>(img.width), static_cast<png_uint_32>(img.height), 8,
               PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  const unsigned ppm = pixels_per_metre(img.pixel_mm);
  png_set_pHYs(png, info, ppm, ppm, PNG_RESOLUTION_METER);
  png_write_info(png, info);
  for (int y = 0; y < img.height; ++y)
    png_write_row(png, const_cast<png_bytep>(&img.grey[static_cast<std::size_t>(y) * img.width]));
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

unsigned pixels_per_metre(double pixel_mm) {
  return static_cast<unsigned>(std::lround(1000.0 / pixel_mm));
}

std::string encode_grey_png(const GreyImage& img) {
  if (img.width <= 0 || img.height <= 0 || img.grey.size() != static_cast<std::size_t>(img.width) * img.height)
    fail("the image is empty");
  if (!(img.pixel_mm > 0)) fail("the pixel size is not positive");
  std::string bytes;
  std::string error = "libpng could not start";
  if (!encode(&bytes, img, &error)) fail(error);
  return bytes;
}

}  // namespace mark
