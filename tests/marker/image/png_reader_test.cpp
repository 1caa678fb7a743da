// The PNG reader against two references it does not share code with: the samples the test wrote
// (through libpng's writer) turned into intensities by the documented rule, and cairo's own PNG
// decoder (the reader this one replaced). Every colour type, depth and interlacing; a declared
// size over the limit refused from the header alone; every truncation and random corruption a
// one-line error naming the file; files read through read_gray_image the same as from memory.
#include <cairo.h>
#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

#include "fonts/error.hpp"
#include "tests/error_of.hpp"
#include "marker/image/gray_image.hpp"
#include "png_writer.hpp"

namespace fs = std::filesystem;

namespace mark::test {
namespace {

// 'path', as the reader names files (built with append: GCC 12 warns falsely, -Wrestrict, on "'" + s).
std::string quoted(const std::string& path) { return std::string(1, '\'').append(path).append(1, '\''); }

// The intensity the reader promises for pixel (x, y) of `spec`: grey as it is, colour as
// 0.299 R + 0.587 G + 0.114 B, alpha composited over white.
double expected(const PngSpec& spec, int x, int y) {
  const std::vector<unsigned> s = spec.pixel(x, y);
  const double max = std::pow(2.0, spec.bit_depth) - 1;
  const auto luma = [](double r, double g, double b) { return 0.299 * r + 0.587 * g + 0.114 * b; };
  double v = 0, a = 1;
  const bool keyed = !spec.transparent_key.empty() && s == spec.transparent_key;
  switch (spec.colour_type) {
    case PNG_COLOR_TYPE_GRAY: v = s[0] / max, a = keyed ? 0 : 1; break;
    case PNG_COLOR_TYPE_GRAY_ALPHA: v = s[0] / max, a = s[1] / max; break;
    case PNG_COLOR_TYPE_RGB: v = luma(s[0] / max, s[1] / max, s[2] / max), a = keyed ? 0 : 1; break;
    case PNG_COLOR_TYPE_RGB_ALPHA: v = luma(s[0] / max, s[1] / max, s[2] / max), a = s[3] / max; break;
    case PNG_COLOR_TYPE_PALETTE: {
      const std::uint8_t* rgb = &spec.palette_rgb[3 * s[0]];
      v = luma(rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0);
      a = s[0] < spec.palette_alpha.size() ? spec.palette_alpha[s[0]] / 255.0 : 1;
      break;
    }
  }
  return v * a + (1 - a);
}

// cairo's decoding of the same bytes, turned into intensities as the old reader did (premultiplied
// ARGB over white). cairo 1.16 reads 16-bit samples as 8.
GrayImage cairo_decode(const std::string& bytes) {
  struct Cursor {
    const std::string* b;
    std::size_t at;
  } cur{&bytes, 0};
  cairo_surface_t* s = cairo_image_surface_create_from_png_stream(
      [](void* c, unsigned char* data, unsigned int n) {
        auto* k = static_cast<Cursor*>(c);
        if (k->at + n > k->b->size()) return CAIRO_STATUS_READ_ERROR;
        std::memcpy(data, k->b->data() + k->at, n);
        k->at += n;
        return CAIRO_STATUS_SUCCESS;
      },
      &cur);
  EXPECT_EQ(cairo_surface_status(s), CAIRO_STATUS_SUCCESS);
  GrayImage img;
  img.width = cairo_image_surface_get_width(s);
  img.height = cairo_image_surface_get_height(s);
  const bool alpha = cairo_image_surface_get_format(s) == CAIRO_FORMAT_ARGB32;
  const unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      std::uint32_t px;
      std::memcpy(&px, data + y * stride + 4 * x, 4);
      const float a = alpha ? ((px >> 24) & 0xFF) / 255.0f : 1.0f;
      img.pixels.push_back(0.299f * ((px >> 16) & 0xFF) / 255.0f + 0.587f * ((px >> 8) & 0xFF) / 255.0f +
                           0.114f * (px & 0xFF) / 255.0f + (1.0f - a));
    }
  cairo_surface_destroy(s);
  return img;
}

// A pattern that reaches every sample value of the depth and differs between neighbours, so a
// pixel put in the wrong place (an interlace pass mis-scattered) shows.
unsigned sample(int x, int y, int channel, int depth) {
  const unsigned max = (1u << depth) - 1;
  return static_cast<unsigned>((x * 7 + y * 13 + channel * 5) * 2654435761u >> 7) % (max + 1);
}

std::vector<PngSpec> every_kind() {
  std::vector<PngSpec> specs;
  const auto add = [&](int type, int depth, int channels) {
    for (const auto& [w, h] : {std::pair{1, 1}, {3, 2}, {9, 7}, {33, 17}})
      for (bool interlaced : {false, true}) {
        PngSpec s;
        s.width = w, s.height = h, s.colour_type = type, s.bit_depth = depth, s.interlaced = interlaced;
        s.pixel = [=](int x, int y) {
          std::vector<unsigned> v;
          for (int c = 0; c < channels; ++c) v.push_back(sample(x, y, c, depth));
          return v;
        };
        specs.push_back(s);
      }
  };
  for (int d : {1, 2, 4, 8, 16}) add(PNG_COLOR_TYPE_GRAY, d, 1);
  for (int d : {8, 16}) {
    add(PNG_COLOR_TYPE_GRAY_ALPHA, d, 2);
    add(PNG_COLOR_TYPE_RGB, d, 3);
    add(PNG_COLOR_TYPE_RGB_ALPHA, d, 4);
  }
  for (int d : {1, 2, 4, 8}) {
    add(PNG_COLOR_TYPE_PALETTE, d, 1);
    const int entries = 1 << d;
    for (int i = 0; i < entries; ++i)
      for (int c = 0; c < 3; ++c) specs.back().palette_rgb.push_back(static_cast<std::uint8_t>((i * 97 + c * 61) % 256));
    // Palette with transparency on its first entries (tRNS).
    for (auto it = specs.end() - 8; it != specs.end(); ++it) {
      it->palette_rgb = specs.back().palette_rgb;
      if (it - (specs.end() - 8) >= 4)
        for (int i = 0; i < std::min(entries, 3); ++i) it->palette_alpha.push_back(static_cast<std::uint8_t>(40 + 90 * i));
    }
  }
  // Colour keys: one grey level and one RGB colour transparent.
  add(PNG_COLOR_TYPE_GRAY, 8, 1);
  for (auto it = specs.end() - 8; it != specs.end(); ++it) it->transparent_key = {sample(0, 0, 0, 8)};
  add(PNG_COLOR_TYPE_RGB, 8, 3);
  for (auto it = specs.end() - 8; it != specs.end(); ++it)
    it->transparent_key = {sample(1, 1, 0, 8), sample(1, 1, 1, 8), sample(1, 1, 2, 8)};
  return specs;
}

std::string describe(const PngSpec& s) {
  return "type " + std::to_string(s.colour_type) + " depth " + std::to_string(s.bit_depth) + " " +
         std::to_string(s.width) + "x" + std::to_string(s.height) + (s.interlaced ? " interlaced" : "") +
         (s.palette_alpha.empty() ? "" : " tRNS") + (s.transparent_key.empty() ? "" : " key");
}

TEST(PngReader, EveryColourTypeDepthAndInterlacingMatchesTheSamplesAndCairo) {
  int compared = 0;
  for (const PngSpec& spec : every_kind()) {
    const std::string bytes = write_png(spec);
    const GrayImage img = decode_png(bytes, "t.png");
    const GrayImage ref = cairo_decode(bytes);
    ASSERT_EQ(img.width, spec.width) << describe(spec);
    ASSERT_EQ(img.height, spec.height) << describe(spec);
    ASSERT_EQ(img.pixels.size(), ref.pixels.size()) << describe(spec);
    double to_samples = 0, to_cairo = 0;
    for (int y = 0; y < spec.height; ++y)
      for (int x = 0; x < spec.width; ++x) {
        to_samples = std::max(to_samples, std::abs(img.at(x, y) - expected(spec, x, y)));
        to_cairo = std::max(to_cairo, static_cast<double>(std::abs(img.at(x, y) - ref.at(x, y))));
      }
    // Float rounding only: the reader is exact to the stored samples.
    EXPECT_LT(to_samples, 1e-6) << describe(spec);
    // cairo rounds premultiplied colour to 8 bits and drops the low byte of 16-bit samples.
    EXPECT_LE(to_cairo, 1.51 / 255) << describe(spec);
    ++compared;
  }
  EXPECT_EQ(compared, 17 * 8);  // 17 kinds, each in 4 sizes, plain and interlaced
}

// The fuzz target's seeds (tests/fuzz/seeds/png/, written once with png_writer: 1-bit grey,
// 16-bit grey interlaced, 16-bit grey + alpha, RGB with a colour key, RGBA interlaced, 4-bit
// palette with tRNS) decode like cairo decodes them.
TEST(PngReader, FuzzSeedsDecodeLikeCairo) {
  int seeds = 0;
  for (const auto& entry : fs::directory_iterator(std::string(MARKER_SOURCE_DIR) + "/tests/fuzz/seeds/png")) {
    std::ifstream in(entry.path(), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const GrayImage img = decode_png(bytes, entry.path().string());
    const GrayImage ref = cairo_decode(bytes);
    ASSERT_EQ(img.pixels.size(), ref.pixels.size()) << entry.path();
    for (std::size_t k = 0; k < img.pixels.size(); ++k)
      ASSERT_NEAR(img.pixels[k], ref.pixels[k], 1.51 / 255) << entry.path() << " pixel " << k;
    ++seeds;
  }
  EXPECT_GE(seeds, 6);
}

TEST(PngReader, RefusesADeclaredSizeOverTheLimitFromTheHeaderAlone) {
  // 20000 x 20000 grey pixels declared, no image data at all: the refusal can only come from the
  // header, before any decoding (a reader that decoded first would report the missing data).
  const std::string bomb = png_header_only(20000, 20000);
  EXPECT_LT(bomb.size(), 64u);
  EXPECT_EQ(error_of([&] { decode_png(bomb, "'bomb.png'"); }),
            "'bomb.png': PNG of 20000x20000 pixels is larger than 100000000 pixels");
  // Found by fuzz_png: the largest sides a header can state, whose product overflows 63 bits.
  EXPECT_EQ(error_of([&] { decode_png(png_header_only(0xFFFFFFFF, 0xFFFFFFFF), "z.png"); }),
            "z.png: PNG of 4294967295x4294967295 pixels is larger than 100000000 pixels");
  EXPECT_EQ(error_of([&] { decode_png(png_header_only(50'000'000, 2), "z.png"); }),
            "z.png: PNG of 50000000x2 pixels: a side is longer than 1000000 pixels");
  EXPECT_EQ(error_of([&] { decode_png(png_header_only(0, 5), "z.png"); }),
            "z.png: PNG of 0x5 pixels: width and height must be at least 1");
  // At the limit the header passes and libpng reports the missing image data.
  EXPECT_EQ(error_of([&] { decode_png(png_header_only(10000, 10000), "z.png"); }),
            "z.png: corrupt PNG data (libpng: IEND: out of place)");
}

TEST(PngReader, EveryTruncationIsOneLineNamingTheFile) {
  PngSpec spec;
  spec.width = 33, spec.height = 17, spec.colour_type = PNG_COLOR_TYPE_RGB_ALPHA;
  spec.pixel = [](int x, int y) { return std::vector<unsigned>{sample(x, y, 0, 8), sample(x, y, 1, 8), 7u, 200u}; };
  const std::string bytes = write_png(spec);
  for (std::size_t cut = 0; cut < bytes.size(); ++cut) {
    const std::string e = error_of([&] { decode_png(bytes.substr(0, cut), "'cut.png'"); });
    ASSERT_EQ(e.rfind("'cut.png': ", 0), 0u) << cut << ": " << e;
    EXPECT_EQ(e.find('\n'), std::string::npos) << e;
    if (cut >= 8 + 8 + 13) {
      EXPECT_EQ(e.rfind("'cut.png': truncated PNG data (libpng: ", 0), 0u) << cut << ": " << e;
    }
  }
  EXPECT_EQ(error_of([&] { decode_png(bytes.substr(0, 20), "c.png"); }),
            "c.png: truncated PNG data: the file ends in its header (20 bytes)");
  EXPECT_EQ(error_of([&] { decode_png("GIF89a", "c.png"); }), "c.png: not a PNG image");
}

TEST(PngReader, RandomCorruptionIsRefusedOrDecodedNeverACrash) {
  PngSpec spec;
  spec.width = 20, spec.height = 9, spec.colour_type = PNG_COLOR_TYPE_GRAY, spec.bit_depth = 8, spec.interlaced = true;
  spec.pixel = [](int x, int y) { return std::vector<unsigned>{sample(x, y, 0, 8)}; };
  const std::string good = write_png(spec);
  std::mt19937 rng(7);
  int decoded = 0, refused = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::string s = good;
    for (int k = 1 + static_cast<int>(rng() % 3); k > 0; --k) s[rng() % s.size()] = static_cast<char>(rng() % 256);
    try {
      const GrayImage img = decode_png(s, "f.png");
      ASSERT_EQ(img.pixels.size(), static_cast<std::size_t>(img.width) * img.height);
      for (float v : img.pixels) ASSERT_TRUE(v >= 0 && v <= 1);
      ++decoded;
    } catch (const InputError& e) {
      ASSERT_EQ(std::string(e.what()).rfind("f.png: ", 0), 0u) << e.what();
      ++refused;
    }
  }
  // Most flips hit a CRC-checked chunk and are refused; flips in the signature's tail or an
  // ancillary byte pass.
  EXPECT_GT(refused, 2000);
  EXPECT_GT(decoded, 0);
}

class ImageFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("png_reader_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  std::string put(const std::string& name, const std::string& bytes) {
    const fs::path p = dir / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p.string();
  }
  fs::path dir;
};

TEST_F(ImageFiles, ReadGrayImageTakesTheFormatFromTheBytesAndQuotesThePath) {
  PngSpec spec;
  spec.width = 5, spec.height = 4;
  spec.pixel = [](int x, int y) { return std::vector<unsigned>{static_cast<unsigned>(x * 50 + y)}; };
  const std::string bytes = write_png(spec);
  // A PNG named .pgm is still a PNG.
  const GrayImage img = read_gray_image(put("named_wrong.pgm", bytes));
  const GrayImage mem = decode_png(bytes, "m");
  EXPECT_EQ(img.pixels, mem.pixels);

  const std::string bomb = put("bomb.png", png_header_only(20000, 20000));
  EXPECT_EQ(error_of([&] { read_gray_image(bomb); }),
            quoted(bomb) + ": PNG of 20000x20000 pixels is larger than 100000000 pixels");
  const std::string cut = put("cut.png", bytes.substr(0, bytes.size() - 20));
  EXPECT_EQ(error_of([&] { read_gray_image(cut); }).rfind(quoted(cut) + ": truncated PNG data (libpng: ", 0), 0u);
  const std::string gif = put("x.gif", "GIF89a....");
  EXPECT_EQ(error_of([&] { read_gray_image(gif); }), quoted(gif) + ": not a PNG or PGM (P2/P5) image");
  const std::string missing = (dir / "missing.png").string();
  EXPECT_EQ(error_of([&] { read_gray_image(missing); }),
            quoted(missing) + ": cannot open the image: No such file or directory");
  EXPECT_EQ(error_of([&] { read_gray_image(dir.string()); }),
            quoted(dir.string()) + ": cannot open the image: it is a directory");
}

TEST_F(ImageFiles, PgmFromAFileEqualsPgmFromMemoryAndStopsAtTheHeader) {
  std::string p5 = "P5\n# 16-bit\n300 200\n60000\n";
  for (int i = 0; i < 300 * 200; ++i) {
    const unsigned v = static_cast<unsigned>(i * 7) % 60001;
    p5.push_back(static_cast<char>(v >> 8));
    p5.push_back(static_cast<char>(v & 0xFF));
  }
  const GrayImage file = read_gray_image(put("a.pgm", p5));
  EXPECT_EQ(file.pixels, parse_pgm(p5, "m").pixels);
  EXPECT_FLOAT_EQ(file.at(1, 0), 7.0f / 60000);
  // A header promising more than the file holds: the same message from the file as from memory.
  const std::string cut = p5.substr(0, p5.size() - 1);
  const std::string path = put("cut.pgm", cut);
  const std::string from_memory = error_of([&] { parse_pgm(cut, quoted(path)); });
  EXPECT_EQ(error_of([&] { read_gray_image(path); }), from_memory);
  EXPECT_NE(from_memory.find("truncated: 60000 samples of 2 byte(s) need 120000 bytes, 119999 left"), std::string::npos);
  const std::string big = put("big.pgm", "P5 20000 20000 255\n");
  EXPECT_EQ(error_of([&] { read_gray_image(big); }),
            quoted(big) + ": PGM byte 18: image of 20000x20000 pixels is larger than 100000000 pixels");
}

}  // namespace
}  // namespace mark::test
