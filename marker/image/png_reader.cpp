// PNG through libpng, row by row: the declared size (IHDR, the first chunk by the PNG spec) is
// checked against kMaxImagePixels before libpng sees the file, so a small file that declares a
// huge image costs nothing; then every row is converted to intensities as it is decoded, so memory
// is the image itself (4 bytes a pixel) plus one row. Every libpng failure is one InputError naming
// the source.
//
// libpng reports errors by longjmp. The two functions that call it (read_header, read_rows) hold
// no C++ object with a destructor in their own frames — the image and the row buffer belong to
// the caller — so a longjmp out of libpng skips nothing that must be destroyed.
#include <png.h>

#include <algorithm>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <vector>

#include "base/error.hpp"
#include "marker/image/gray_image.hpp"
#include "marker/image/image_source.hpp"

namespace mark {
namespace {

constexpr std::size_t kSignatureBytes = 8;
// Signature, IHDR length and type, 13 data bytes: enough to read the declared size.
constexpr std::size_t kHeaderBytes = kSignatureBytes + 8 + 13;

std::uint32_t big_endian32(const unsigned char* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | p[3];
}

// What libpng reads from, and what it said when it failed.
struct PngStream {
  ImageSource* source = nullptr;
  bool truncated = false;
  char message[256] = "";
};

void on_error(png_structp png, png_const_charp message) {
  auto* s = static_cast<PngStream*>(png_get_error_ptr(png));
  std::snprintf(s->message, sizeof s->message, "%s", message ? message : "unknown error");
  png_longjmp(png, 1);
}

// Warnings (an sRGB profile libpng dislikes, a CRC error in an ancillary chunk it then skips)
// change nothing in the pixels: not reported.
void on_warning(png_structp, png_const_charp) {}

void on_read(png_structp png, png_bytep data, png_size_t length) {
  auto* s = static_cast<PngStream*>(png_get_io_ptr(png));
  const std::size_t got = s->source->read(data, length);
  if (got != length) {
    s->truncated = true;
    png_error(png, "the file ends inside a chunk");
  }
}

struct PngHeader {
  png_uint_32 width = 0, height = 0;
  int interlace = 0, passes = 1, channels = 0, bit_depth = 0;
  std::size_t row_bytes = 0;
};

// Reads the chunks up to the first IDAT and sets the transforms: palette and low-depth grey
// expanded to 8 bits, a tRNS colour key to alpha; 16-bit samples kept (no precision lost).
bool read_header(png_structp png, png_infop info, PngHeader& h) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_info(png, info);
  int colour = 0;
  png_get_IHDR(png, info, &h.width, &h.height, &h.bit_depth, &colour, &h.interlace, nullptr, nullptr);
  png_set_expand(png);
  // Interlaced rows are taken pass by pass, each placed where it belongs (read_rows): libpng's
  // own interlace handling would need the whole image buffered in its format first.
  h.passes = h.interlace == PNG_INTERLACE_ADAM7 ? PNG_INTERLACE_ADAM7_PASSES : 1;
  png_read_update_info(png, info);
  h.channels = png_get_channels(png, info);
  h.bit_depth = png_get_bit_depth(png, info);
  h.row_bytes = png_get_rowbytes(png, info);
  return true;
}

// One decoded row (`columns` pixels) to intensities at out[0], out[step], ...: grey as it is,
// colour as luma (ITU-R BT.601, on the stored values), alpha composited over white.
void convert_row(const unsigned char* row, const PngHeader& h, png_uint_32 columns, float* out,
                 std::size_t step) {
  const bool wide = h.bit_depth == 16;
  const float scale = wide ? 1.0f / 65535.0f : 1.0f / 255.0f;
  const auto sample = [&](std::size_t k) {
    return static_cast<float>(wide ? (row[2 * k] << 8) | row[2 * k + 1] : row[k]) * scale;
  };
  const int c = h.channels;
  for (png_uint_32 x = 0; x < columns; ++x) {
    const std::size_t k = static_cast<std::size_t>(x) * c;
    const float v = c <= 2 ? sample(k) : 0.299f * sample(k) + 0.587f * sample(k + 1) + 0.114f * sample(k + 2);
    const float alpha = c == 2 || c == 4 ? sample(k + c - 1) : 1.0f;
    out[x * step] = v * alpha + (1.0f - alpha);
  }
}

// Decodes every row into `pixels` (width × height, row-major), `row` holding one decoded row.
// A plain image grows row by row (capacity reserved, pages touched only as rows arrive), so a file
// that ends early costs what it held, not what it declared; an interlaced one needs the whole
// image from its first pass on.
bool read_rows(png_structp png, const PngHeader& h, std::vector<float>& pixels, unsigned char* row) {
  if (setjmp(png_jmpbuf(png))) return false;
  const bool interlaced = h.passes > 1;
  const std::size_t width = h.width;
  if (interlaced)
    pixels.assign(width * h.height, 1.0f);
  else
    pixels.reserve(width * h.height);
  for (int pass = 0; pass < h.passes; ++pass) {
    const png_uint_32 columns = interlaced ? PNG_PASS_COLS(h.width, pass) : h.width;
    const png_uint_32 rows = interlaced ? PNG_PASS_ROWS(h.height, pass) : h.height;
    if (columns == 0 || rows == 0) continue;  // libpng skips the empty passes of small images too
    for (png_uint_32 r = 0; r < rows; ++r) {
      png_read_row(png, row, nullptr);
      if (!interlaced) {
        pixels.resize(pixels.size() + width);
        convert_row(row, h, columns, pixels.data() + r * width, 1);
        continue;
      }
      const std::size_t y = PNG_ROW_FROM_PASS_ROW(r, pass), x0 = PNG_COL_FROM_PASS_COL(0, pass);
      convert_row(row, h, columns, pixels.data() + y * width + x0, std::size_t{1} << PNG_PASS_COL_SHIFT(pass));
    }
  }
  png_read_end(png, nullptr);
  return true;
}

struct PngReadStruct {
  png_structp png = nullptr;
  png_infop info = nullptr;
  ~PngReadStruct() { png_destroy_read_struct(&png, info ? &info : nullptr, nullptr); }
};

}  // namespace

GrayImage read_png(ImageSource& source, const std::string& name) {
  const auto fail = [&](const std::string& what) -> GrayImage { throw InputError(name + ": " + what); };

  unsigned char head[kHeaderBytes];
  const std::size_t got = source.read(head, kHeaderBytes);
  if (got < kSignatureBytes || png_sig_cmp(head, 0, kSignatureBytes) != 0) return fail("not a PNG image");
  if (got < kHeaderBytes) return fail("truncated PNG data: the file ends in its header (" + std::to_string(got) + " bytes)");
  if (std::memcmp(head + 12, "IHDR", 4) != 0) return fail("corrupt PNG data: the first chunk is not IHDR");
  const std::uint32_t w = big_endian32(head + 16), h = big_endian32(head + 20);
  if (w < 1 || h < 1) return fail("PNG of " + std::to_string(w) + "x" + std::to_string(h) + " pixels: width and height must be at least 1");
  // Both sides are below 2^32, so their product fits 64 unsigned bits.
  if (std::uint64_t{w} * h > static_cast<std::uint64_t>(kMaxImagePixels))
    return fail("PNG of " + std::to_string(w) + "x" + std::to_string(h) + " pixels is larger than " +
                std::to_string(kMaxImagePixels) + " pixels");
  // libpng's own limit on a side (which keeps its row buffer small): said here in our words.
  if (w > PNG_USER_WIDTH_MAX || h > PNG_USER_HEIGHT_MAX)
    return fail("PNG of " + std::to_string(w) + "x" + std::to_string(h) + " pixels: a side is longer than " +
                std::to_string(PNG_USER_WIDTH_MAX) + " pixels");
  if (!source.rewind()) return fail("cannot read the file again after its header");

  PngStream stream;
  stream.source = &source;
  PngReadStruct s;
  s.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &stream, on_error, on_warning);
  if (s.png) s.info = png_create_info_struct(s.png);
  if (!s.png || !s.info) return fail("cannot start libpng (out of memory)");
  png_set_read_fn(s.png, &stream, on_read);
  // Only the chunks that make the pixels are read; text, ICC profiles and the like are skipped
  // unread, so no compressed metadata is ever inflated.
  png_set_keep_unknown_chunks(s.png, PNG_HANDLE_CHUNK_NEVER, nullptr, -1);

  PngHeader header;
  const auto libpng_failed = [&]() -> GrayImage {
    const std::string why = std::string("(libpng: ") + stream.message + ")";
    return fail(stream.truncated ? "truncated PNG data " + why : "corrupt PNG data " + why);
  };
  if (!read_header(s.png, s.info, header)) return libpng_failed();
  if (header.width != w || header.height != h) return fail("corrupt PNG data: the size changed while reading");

  GrayImage img;
  img.width = static_cast<int>(w);
  img.height = static_cast<int>(h);
  std::vector<unsigned char> row(header.row_bytes);
  if (!read_rows(s.png, header, img.pixels, row.data())) return libpng_failed();
  return img;
}

GrayImage decode_png(std::string_view bytes, const std::string& source) {
  MemoryImageSource memory(bytes);
  return read_png(memory, source);
}

}  // namespace mark
