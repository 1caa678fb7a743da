// ZBar: QR and Code 128 (GS1-128 too: ZBar reports its FNC1 separators as GS and drops the
// leading FNC1, flagging the symbol as GS1). Binary mode keeps QR byte data as bytes instead of
// guessing a text encoding. ZBar scans along rows and columns: a linear code must reach it with
// its bars upright (verify.cpp turns the picture back by the code's angle).
#include <zbar.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "marker/codes/code_reader.hpp"

namespace mark {
namespace {

using namespace zbar;

struct ScannerDeleter {
  void operator()(zbar_image_scanner_t* s) const { zbar_image_scanner_destroy(s); }
};
struct ImageDeleter {
  void operator()(zbar_image_t* i) const { zbar_image_destroy(i); }
};

double side(const zbar_symbol_t* s, unsigned a, unsigned b) {
  return std::hypot(zbar_symbol_get_loc_x(s, a) - zbar_symbol_get_loc_x(s, b),
                    zbar_symbol_get_loc_y(s, a) - zbar_symbol_get_loc_y(s, b));
}

class ZbarReader final : public CodeReader {
 public:
  std::string_view name() const override { return "zbar"; }
  bool supports(Symbology s, int, int) const override {
    return s == Symbology::qr || s == Symbology::code128 || s == Symbology::gs1_128;
  }
  ReadResult read(const GreyImage& image, const SymbolInfo& symbol) const override;
};

ReadResult ZbarReader::read(const GreyImage& image, const SymbolInfo& symbol) const {
  ReadResult r;
  r.reader = "zbar";
  if (!supports(symbol.symbology, symbol.rows, symbol.cols)) return r;
  std::unique_ptr<zbar_image_scanner_t, ScannerDeleter> scanner(zbar_image_scanner_create());
  const zbar_symbol_type_t type = symbol.symbology == Symbology::qr ? ZBAR_QRCODE : ZBAR_CODE128;
  zbar_image_scanner_set_config(scanner.get(), ZBAR_NONE, ZBAR_CFG_ENABLE, 0);
  zbar_image_scanner_set_config(scanner.get(), type, ZBAR_CFG_ENABLE, 1);
  zbar_image_scanner_set_config(scanner.get(), type, ZBAR_CFG_BINARY, 1);
  std::unique_ptr<zbar_image_t, ImageDeleter> img(zbar_image_create());
  zbar_image_set_format(img.get(), zbar_fourcc('Y', '8', '0', '0'));
  zbar_image_set_size(img.get(), static_cast<unsigned>(image.width), static_cast<unsigned>(image.height));
  zbar_image_set_data(img.get(), image.grey.data(), image.grey.size(), nullptr);
  if (zbar_scan_image(scanner.get(), img.get()) <= 0) return r;
  for (const zbar_symbol_t* s = zbar_image_first_symbol(img.get()); s; s = zbar_symbol_next(s)) {
    if (zbar_symbol_get_type(s) != type) continue;
    r.decoded = true;
    r.data.assign(zbar_symbol_get_data(s), zbar_symbol_get_data_length(s));
    const unsigned n = zbar_symbol_get_loc_size(s);
    if (symbol.symbology == Symbology::qr && n == 4) {
      // The four corners of the symbol, in order around it.
      r.module_y_px = (side(s, 0, 1) + side(s, 3, 2)) / 2 / symbol.rows;
      r.module_x_px = (side(s, 0, 3) + side(s, 1, 2)) / 2 / symbol.cols;
    } else if (n >= 2) {
      // ZBar leaves the two ends of each scan line across the bars as consecutive points (the
      // symbol's first and last bar edge): the longest such pair is the symbol's width.
      double width = 0;
      for (unsigned k = 0; k + 1 < n; ++k) width = std::max(width, side(s, k, k + 1));
      r.module_x_px = width / symbol.cols;
    }
    break;
  }
  // zbar_image_set_data with no cleanup handler leaves our buffer to us.
  return r;
}

}  // namespace

const CodeReader& zbar_reader() {
  static const ZbarReader reader;
  return reader;
}

}  // namespace mark
