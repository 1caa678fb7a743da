// ZXing-C++ (Debian libzxing 1.4): Data Matrix, QR and Code 128 with one decoder family that
// shares no code with libdmtx or ZBar — the second opinion on every symbology. It reads the
// 144 × 144 Data Matrix libdmtx cannot. Its bytes() are the symbol's data as encoded: FNC1
// separators as GS, the leading FNC1 of a GS1 symbol left out (it is in the symbology
// identifier), QR byte mode as bytes.
#include <ZXing/ReadBarcode.h>

#include <cmath>

#include "marker/codes/code_reader.hpp"

namespace mark {
namespace {

double distance(const ZXing::PointI& a, const ZXing::PointI& b) { return std::hypot(a.x - b.x, a.y - b.y); }

ZXing::BarcodeFormat format_of(Symbology s) {
  switch (s) {
    case Symbology::datamatrix:
    case Symbology::gs1_datamatrix: return ZXing::BarcodeFormat::DataMatrix;
    case Symbology::qr: return ZXing::BarcodeFormat::QRCode;
    case Symbology::code128:
    case Symbology::gs1_128: return ZXing::BarcodeFormat::Code128;
  }
  return ZXing::BarcodeFormat::None;
}

class ZxingReader final : public CodeReader {
 public:
  std::string_view name() const override { return "zxing"; }
  bool supports(Symbology, int, int) const override { return true; }
  ReadResult read(const GreyImage& image, const SymbolInfo& symbol) const override;
};

ReadResult ZxingReader::read(const GreyImage& image, const SymbolInfo& symbol) const {
  ReadResult r;
  r.reader = "zxing";
  if (image.empty()) return r;
  const ZXing::ImageView view(image.grey.data(), image.width, image.height, ZXing::ImageFormat::Lum);
  // ZXing's default local-average binarizer is made for phone pictures of print: on a DPM
  // picture whose modules span several of its 8-pixel blocks it loses a mark of moderate
  // contrast (a clean 27 % cell contrast Data Matrix, 0 modules wrong, is not read), which the
  // global histogram reads. A fixed-mount reader tries several binarizations; so does this.
  ZXing::Result result;
  for (const ZXing::Binarizer binarizer : {ZXing::Binarizer::LocalAverage, ZXing::Binarizer::GlobalHistogram}) {
    ZXing::DecodeHints hints;
    hints.setFormats(format_of(symbol.symbology));
    hints.setTryHarder(true);
    hints.setTryRotate(true);
    hints.setTryDownscale(false);  // the picture is the camera's resolution: nothing to gain
    hints.setBinarizer(binarizer);
    result = ZXing::ReadBarcode(view, hints);
    if (result.isValid()) break;
  }
  if (!result.isValid()) return r;
  r.decoded = true;
  const ZXing::ByteArray& bytes = result.bytes();
  r.data.assign(bytes.begin(), bytes.end());
  // The symbol's corners: top-left, top-right, bottom-right, bottom-left.
  const ZXing::Position& p = result.position();
  if (is_linear(symbol.symbology)) {
    r.module_x_px = distance(p.topLeft(), p.topRight()) / symbol.cols;
  } else {
    r.module_x_px = (distance(p.topLeft(), p.topRight()) + distance(p.bottomLeft(), p.bottomRight())) / 2 / symbol.cols;
    r.module_y_px = (distance(p.topLeft(), p.bottomLeft()) + distance(p.topRight(), p.bottomRight())) / 2 / symbol.rows;
  }
  return r;
}

}  // namespace

const CodeReader& zxing_reader() {
  static const ZxingReader reader;
  return reader;
}

}  // namespace mark
