#pragma once
// Test artwork for the gravure suites: a step wedge (11 tone steps, 0 … 100 %) over a band of
// fine line-work (lines one and two density values wide — the double-frequency and shifted
// cells of FIG. 4 and 4A — and short dashes), with the matching line-work mask, at four pixels
// a cell along the track for a 70 lines/cm screen (28 px/mm).
#include <algorithm>
#include <cmath>
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

// Issue 23's test set, at four pixels a cell along the track (70 lines/cm, 28 px/mm), in four
// bands along the track (each a quarter of the width, the full height):
//  1. a photo-like gradient (smooth waves of 5 … 95 % density);
//  2. anti-aliased type over that photo: dark strokes and rings ("I", "O", "/") whose edges are
//     the coverage of a 4 × 4 supersampling, so every grey level sits beside full black;
//  3. hard edges: black and white squares 6 px wide, out of step with the 4 px cells;
//  4. single cells beside channels: black tracks broken every fourth cell by one cell half grey
//     (5 … 85 %), half black (52 … 92 % density, its density at one end of the cell).
// `mask` (if given) marks bands 2–4 as line-work.
inline double photo_density(double x, double y) {
  return 0.5 + 0.3 * std::sin(x * 0.11) * std::cos(y * 0.07) + 0.15 * std::sin((x + 2 * y) * 0.031);
}

// Whether a point is inside the glyphs of band 2 (u, v in pixels from the band's corner).
inline bool on_glyph(double u, double v, double height) {
  const double size = height * 0.8, top = height * 0.1, stroke = size * 0.14;
  const double cell = size * 0.9;  // glyph advance
  const int glyph = static_cast<int>(u / cell) % 3;
  const double gx = std::fmod(u, cell) - cell / 2, gy = v - top - size / 2;
  if (std::abs(gy) > size / 2 + stroke) return false;
  switch (glyph) {
    case 0: return std::abs(gx) < stroke / 2 && std::abs(gy) <= size / 2;  // I
    case 1: {                                                                // O
      const double r = std::hypot(gx / 0.8, gy);
      return r > size / 2 - stroke && r < size / 2;
    }
    default: return std::abs(gx + gy * 0.45) < stroke / 2 && std::abs(gy) <= size / 2;  // /
  }
}

inline GrayImage gravure_test_set(int width = 448, int height = 112, GrayImage* mask = nullptr) {
  GrayImage img{width, height, std::vector<float>(static_cast<std::size_t>(width) * height, 1.0f)};
  if (mask) *mask = GrayImage{width, height, std::vector<float>(img.pixels.size(), 1.0f)};
  const int band = width / 4;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      double density = 0;
      const int b = std::min(3, x / band), u = x - b * band;
      if (b == 0) {
        density = photo_density(x, y);
      } else if (b == 1) {
        int covered = 0;  // two lines of type
        const double line = height / 2.0;
        for (int sy = 0; sy < 4; ++sy)
          for (int sx = 0; sx < 4; ++sx)
            covered += on_glyph(u + (sx + 0.5) / 4, std::fmod(y + (sy + 0.5) / 4, line), line);
        const double ink = covered / 16.0;
        density = ink + (1 - ink) * photo_density(x, y);
      } else if (b == 2) {
        density = ((u / 6) + (y / 6)) % 2 == 0 ? 1 : 0;
      } else {
        // One odd cell in each black track every fourth cell: half of it grey, half black, the
        // grey half first or last, so its density sits at one end and its exit or entry lands
        // next to the neighbouring channel.
        const int track = y / 4, cell = u / 4;
        density = 1;
        if (cell % 4 == 2) {
          const double grey = 0.05 + 0.8 * ((track * 7 + cell) % 13) / 12.0;
          const bool grey_first = (track + cell / 4) % 2 == 0;
          density = (u % 4 < 2) == grey_first ? grey : 1.0;
        }
      }
      if (mask && b > 0) mask->pixels[static_cast<std::size_t>(y) * width + x] = 0;
      // Density 0 … 1 is the grey value 1 … 0 (white is no cell).
      img.pixels[static_cast<std::size_t>(y) * width + x] = static_cast<float>(1 - std::clamp(density, 0.0, 1.0));
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
