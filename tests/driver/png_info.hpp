#pragma once
// Reads a PNG's size and its pHYs chunk back with libpng, for the tests of pictures that carry
// their pixel size.
#include <png.h>

#include <cstdio>
#include <string>

namespace mark::test {

struct PngInfo {
  int width = 0;
  int height = 0;
  unsigned ppm_x = 0, ppm_y = 0;  // pixels per unit
  int unit = -1;                  // PNG_RESOLUTION_METER when set
  bool read = false;
};

inline PngInfo read_png_info(const std::string& path) {
  PngInfo info;
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return info;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop pi = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png)) == 0) {
    png_init_io(png, f);
    png_read_info(png, pi);
    png_uint_32 x = 0, y = 0;
    png_get_pHYs(png, pi, &x, &y, &info.unit);
    info.ppm_x = x;
    info.ppm_y = y;
    info.width = static_cast<int>(png_get_image_width(png, pi));
    info.height = static_cast<int>(png_get_image_height(png, pi));
    info.read = true;
  }
  png_destroy_read_struct(&png, &pi, nullptr);
  std::fclose(f);
  return info;
}

}  // namespace mark::test
