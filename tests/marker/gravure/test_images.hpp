#pragma once
// Test artwork for the gravure suites: a step wedge (11 tone steps, 0 … 100 %) over a band of
// fine line-work (lines one and two density values wide — the double-frequency and shifted
// cells of FIG. 4 and 4A — and short dashes), with the matching line-work mask, at four pixels
// a cell along the track for a 70 lines/cm screen (28 px/mm).
#include <cstdint>
#include <fstream>
#include <string>

#include "marker/image/gray_image.hpp"

namespace mark::test {

inline GrayImage wedge_and_lines(int width = 280, int height = 112, GrayImage* mask = nullptr) {
  GrayImage img{width, height, std::vector<float>(static_cast<std::size_t>(width) * height, 1.0f)};
  if (mask) *mask = GrayImage{width, height, std::vector<float>(img.pixels.size(), 1.0f)};
  const int half = height / 2;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      float v = 1;
      if (y < half) {
        v = 1.0f - static_cast<float>(std::min(10, x * 11 / width)) / 10;  // the wedge
      } else {
        if (mask) mask->pixels[static_cast<std::size_t>(y) * width + x] = 0;  // line-work
        const int band = x * 4 / width;
        if (band == 0) v = (x + 1) % 4 < 2 ? 0 : 1;        // ■□□■ cells: double frequency
        else if (band == 1) v = x % 4 < 2 ? 0 : 1;         // ■■□□ cells: shifted (FIG. 4A)
        else if (band == 2) v = x % 8 < 1 ? 0 : 1;         // one-value hairlines
        else v = (y / 3) % 2 == 0 && (x / 12) % 2 == 0 ? 0 : 1;  // dashes across the tracks
      }
      img.pixels[static_cast<std::size_t>(y) * width + x] = v;
    }
  return img;
}

// Binary PGM (P5, 8 bit) at `path`. (Not write_pgm: tool_render.hpp has a mark::test::write_pgm
// with the same parameters, and two such functions are one symbol to the linker.)
inline void save_pgm(const GrayImage& img, const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  out << "P5\n" << img.width << " " << img.height << "\n255\n";
  for (float v : img.pixels) out.put(static_cast<char>(static_cast<std::uint8_t>(std::lround(v * 255))));
}

}  // namespace mark::test
