// libdmtx: find the symbol's L-shaped finder, fit its grid, decode. FNC1 is returned as GS
// (0x1D) so GS1 data comes back as its element string; the leading FNC1 that marks a GS1 symbol
// is stripped, as a scanner transmitting the symbology identifier ]d2 would.
#include <dmtx.h>

#include <cmath>
#include <vector>

#include "marker/codes/code_reader.hpp"

namespace mark {
namespace {

double distance(const DmtxVector2& a, const DmtxVector2& b) { return std::hypot(a.X - b.X, a.Y - b.Y); }

class DmtxReader final : public CodeReader {
 public:
  std::string_view name() const override { return "libdmtx"; }
  bool supports(Symbology s, int rows, int cols) const override {
    // libdmtx 0.7.7 interleaves the 144 × 144 symbol's blocks its own way and cannot read the
    // standard's (every perfect 144 × 144 zint mark reads "not decoded"; ZXing reads them).
    return (s == Symbology::datamatrix || s == Symbology::gs1_datamatrix) && !(rows == 144 && cols == 144);
  }
  ReadResult read(const GreyImage& image, const SymbolInfo& symbol) const override;
};

ReadResult DmtxReader::read(const GreyImage& image, const SymbolInfo& symbol) const {
  ReadResult r;
  r.reader = "libdmtx";
  std::vector<unsigned char> pixels(image.grey.begin(), image.grey.end());
  DmtxImage* img = dmtxImageCreate(pixels.data(), image.width, image.height, DmtxPack8bppK);
  if (!img) return r;
  DmtxDecode* dec = dmtxDecodeCreate(img, 1);
  if (!dec) {
    dmtxImageDestroy(&img);
    return r;
  }
  dmtxDecodeSetProp(dec, DmtxPropFnc1, 0x1d);
  // A symbol is at least one module square per pixel row; the reader skips nothing larger.
  dmtxDecodeSetProp(dec, DmtxPropScanGap, 1);
  DmtxTime timeout = dmtxTimeAdd(dmtxTimeNow(), 5000);
  DmtxRegion* reg = dmtxRegionFindNext(dec, &timeout);
  if (reg) {
    if (DmtxMessage* msg = dmtxDecodeMatrixRegion(dec, reg, DmtxUndefined)) {
      r.decoded = true;
      r.data.assign(reinterpret_cast<const char*>(msg->output), static_cast<std::size_t>(msg->outputIdx));
      if (!r.data.empty() && r.data.front() == '\x1d') r.data.erase(0, 1);
      // The fitted grid's unit square spans the whole symbol.
      DmtxVector2 p00{0, 0}, p10{1, 0}, p01{0, 1}, a, b, c;
      dmtxMatrix3VMultiply(&a, &p00, reg->fit2raw);
      dmtxMatrix3VMultiply(&b, &p10, reg->fit2raw);
      dmtxMatrix3VMultiply(&c, &p01, reg->fit2raw);
      const int sr = reg->symbolRows > 0 ? reg->symbolRows : symbol.rows;
      const int sc = reg->symbolCols > 0 ? reg->symbolCols : symbol.cols;
      r.module_x_px = distance(a, b) / sc;
      r.module_y_px = distance(a, c) / sr;
      dmtxMessageDestroy(&msg);
    }
    dmtxRegionDestroy(&reg);
  }
  dmtxDecodeDestroy(&dec);
  dmtxImageDestroy(&img);
  return r;
}

}  // namespace

const CodeReader& dmtx_reader() {
  static const DmtxReader reader;
  return reader;
}

}  // namespace mark
