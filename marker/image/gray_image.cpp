// Reading a grey-level image file: the format from its first bytes, then the PNG or PGM reader,
// both reading the file as they decode it.
#include "marker/image/gray_image.hpp"

#include "base/error.hpp"
#include "marker/image/image_source.hpp"

namespace mark {

GrayImage read_gray_image(const std::string& path) {
  const std::string name = "'" + path + "'";
  FileImageSource file(path);
  unsigned char magic[2] = {0, 0};
  const std::size_t got = file.read(magic, sizeof magic);
  if (!file.rewind()) throw InputError(name + ": cannot read the image again after its first bytes");
  if (got == 2 && magic[0] == 0x89 && magic[1] == 'P') return read_png(file, name);
  if (got == 2 && magic[0] == 'P' && (magic[1] == '2' || magic[1] == '5')) return read_pgm(file, name);
  throw InputError(name + ": not a PNG or PGM (P2/P5) image");
}

}  // namespace mark
