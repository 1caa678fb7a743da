#include "tool_render.hpp"

#include <cairo.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <vector>

namespace mark::test {

GrayImage render(const Render& r, const std::function<bool(double, double)>& inside,
                 const std::function<bool(double, double)>& near_edge) {
  GrayImage img;
  img.width = img.height = r.size;
  img.pixels.resize(static_cast<std::size_t>(r.size) * r.size);
  for (int y = 0; y < r.size; ++y)
    for (int x = 0; x < r.size; ++x) {
      double cover;
      if (!near_edge(x + 0.5, y + 0.5)) {
        cover = inside(x + 0.5, y + 0.5) ? 1 : 0;
      } else {
        int n = 0;
        for (int i = 0; i < 8; ++i)
          for (int j = 0; j < 8; ++j) n += inside(x + (i + 0.5) / 8, y + (j + 0.5) / 8);
        cover = n / 64.0;
      }
      img.pixels[static_cast<std::size_t>(y) * r.size + x] = static_cast<float>(r.bright + (r.dark - r.bright) * cover);
    }
  if (r.blur_px > 0) {
    const int k = static_cast<int>(std::ceil(3 * r.blur_px));
    std::vector<double> w(2 * k + 1);
    double sum = 0;
    for (int i = -k; i <= k; ++i) sum += w[i + k] = std::exp(-i * i / (2 * r.blur_px * r.blur_px));
    for (double& v : w) v /= sum;
    for (int pass = 0; pass < 2; ++pass) {
      std::vector<float> out(img.pixels.size());
      for (int y = 0; y < r.size; ++y)
        for (int x = 0; x < r.size; ++x) {
          double acc = 0;
          for (int i = -k; i <= k; ++i) {
            const int xx = std::clamp(pass == 0 ? x + i : x, 0, r.size - 1);
            const int yy = std::clamp(pass == 0 ? y : y + i, 0, r.size - 1);
            acc += w[i + k] * img.at(xx, yy);
          }
          out[static_cast<std::size_t>(y) * r.size + x] = static_cast<float>(acc);
        }
      img.pixels = out;
    }
  }
  std::mt19937 rng(r.seed);
  std::normal_distribution<double> noise(0, r.noise > 0 ? r.noise : 1);
  for (float& p : img.pixels) {
    double v = p + (r.noise > 0 ? noise(rng) : 0);
    v = std::round(std::clamp(v, 0.0, 1.0) * 255) / 255;  // an 8-bit camera
    p = static_cast<float>(v);
  }
  return img;
}

GrayImage disk(const Render& r, Point c, double radius) {
  return render(
      r, [=](double x, double y) { return (Point(x, y) - c).norm() <= radius; },
      [=](double x, double y) { return std::abs((Point(x, y) - c).norm() - radius) < 1.5; });
}

GrayImage chipped_disk(const Render& r, Point c, double radius, double chip_deg) {
  const double a = chip_deg * M_PI / 180;
  const Point chip = c + (radius + 6) * Point(std::cos(a), -std::sin(a));
  const double bite = 14;
  return render(
      r, [=](double x, double y) { return (Point(x, y) - c).norm() <= radius && (Point(x, y) - chip).norm() > bite; },
      [=](double x, double y) {
        return std::abs((Point(x, y) - c).norm() - radius) < 1.5 || std::abs((Point(x, y) - chip).norm() - bite) < 1.5;
      });
}

std::string write_pgm(const GrayImage& img, const std::string& name) {
  const auto path = std::filesystem::path(MARKER_BINARY_DIR) / "tool_images" / (name + ".pgm");
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << "P5\n# synthetic tool shadow\n" << img.width << " " << img.height << "\n255\n";
  for (float p : img.pixels) out.put(static_cast<char>(std::lround(p * 255)));
  return path.string();
}

std::string write_png(const GrayImage& img, const std::string& name) {
  const auto path = std::filesystem::path(MARKER_BINARY_DIR) / "tool_images" / (name + ".png");
  std::filesystem::create_directories(path.parent_path());
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, img.width, img.height);
  unsigned char* d = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const std::uint32_t v = static_cast<std::uint32_t>(std::lround(img.at(x, y) * 255));
      const std::uint32_t px = 0xFF000000u | v << 16 | v << 8 | v;
      std::memcpy(d + y * stride + 4 * x, &px, 4);
    }
  cairo_surface_mark_dirty(s);
  EXPECT_EQ(cairo_surface_write_to_png(s, path.c_str()), CAIRO_STATUS_SUCCESS);
  cairo_surface_destroy(s);
  return path.string();
}


}  // namespace mark::test
