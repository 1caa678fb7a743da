// Reading a grey-level image: PNG through Cairo, PGM through our parser.
#include "marker/image/gray_image.hpp"

#include <cairo.h>

#include <cstring>
#include <fstream>
#include <sstream>

#include "base/error.hpp"

namespace mark {
namespace {

GrayImage from_cairo(cairo_surface_t* s, const std::string& path) {
  const cairo_format_t f = cairo_image_surface_get_format(s);
  GrayImage img;
  img.width = cairo_image_surface_get_width(s);
  img.height = cairo_image_surface_get_height(s);
  if (static_cast<std::int64_t>(img.width) * img.height > kMaxImagePixels)
    throw InputError(path + ": image larger than " + std::to_string(kMaxImagePixels) + " pixels");
  cairo_surface_flush(s);
  const unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  img.pixels.resize(static_cast<std::size_t>(img.width) * img.height);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      float v = 1.0f;
      if (f == CAIRO_FORMAT_ARGB32 || f == CAIRO_FORMAT_RGB24) {
        std::uint32_t px;
        std::memcpy(&px, data + y * stride + 4 * x, 4);
        const float a = f == CAIRO_FORMAT_ARGB32 ? ((px >> 24) & 0xFF) / 255.0f : 1.0f;
        // Premultiplied colour over a white background: transparent pixels read as bright.
        const float r = ((px >> 16) & 0xFF) / 255.0f, g = ((px >> 8) & 0xFF) / 255.0f, b = (px & 0xFF) / 255.0f;
        v = 0.299f * r + 0.587f * g + 0.114f * b + (1.0f - a);
      } else if (f == CAIRO_FORMAT_A8) {
        v = data[y * stride + x] / 255.0f;
      } else {
        throw InputError(path + ": unsupported PNG pixel format");
      }
      img.pixels[static_cast<std::size_t>(y) * img.width + x] = v;
    }
  return img;
}

}  // namespace

GrayImage read_gray_image(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the image");
  std::ostringstream ss;
  ss << in.rdbuf();
  const std::string bytes = ss.str();
  if (bytes.size() >= 8 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0) {
    cairo_surface_t* s = cairo_image_surface_create_from_png(path.c_str());
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
      const std::string why = cairo_status_to_string(cairo_surface_status(s));
      cairo_surface_destroy(s);
      throw InputError(path + ": unreadable PNG (" + why + ")");
    }
    try {
      GrayImage img = from_cairo(s, path);
      cairo_surface_destroy(s);
      return img;
    } catch (...) {
      cairo_surface_destroy(s);
      throw;
    }
  }
  if (bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == '2' || bytes[1] == '5')) return parse_pgm(bytes, path);
  throw InputError(path + ": not a PNG or PGM (P2/P5) image");
}

}  // namespace mark
