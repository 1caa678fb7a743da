#pragma once
// Real decoders behind one interface, reading the camera's picture of a code: ZXing-C++ (Data
// Matrix, QR, Code 128), libdmtx (Data Matrix) and ZBar (QR, Code 128) — so "decodes" means
// what it means on the line, and two independent decoders can be asked to agree. Each returns
// the decoded bytes (GS1: the element string, FNC1 separators as GS, the leading FNC1 that marks
// a GS1 symbol dropped, as a scanner sending the symbology identifier would) and the module
// pitch it found, in picture pixels.
#include <string>
#include <string_view>
#include <vector>

#include "base/grey_image.hpp"
#include "marker/codes/symbology.hpp"

namespace mark {

// What the reader is told about the symbol it looks for.
struct SymbolInfo {
  Symbology symbology = Symbology::datamatrix;
  int rows = 0, cols = 0;  // modules (linear codes: 1 row)
};

struct ReadResult {
  std::string reader;  // "zxing", "libdmtx" or "zbar"
  bool decoded = false;
  std::string data;    // bytes as the reader returns them
  // The module pitch the reader found, in picture pixels, along the symbol's rows (x) and
  // columns (y); y is 0 for a linear code, both 0 when the reader does not say.
  double module_x_px = 0;
  double module_y_px = 0;
};

class CodeReader {
 public:
  virtual ~CodeReader() = default;
  virtual std::string_view name() const = 0;
  // Whether the reader decodes such a symbol at all. libdmtx 0.7.7 does not decode a 144 × 144
  // Data Matrix as zint (and ISO/IEC 16022) interleaves it.
  virtual bool supports(Symbology symbology, int rows, int cols) const = 0;
  // Dark modules must be dark in the picture.
  virtual ReadResult read(const GreyImage& picture, const SymbolInfo& symbol) const = 0;
};

const CodeReader& zxing_reader();
const CodeReader& dmtx_reader();
const CodeReader& zbar_reader();

// Every reader, in the order they are reported: zxing, libdmtx, zbar.
const std::vector<const CodeReader*>& code_readers();
// The reader of that name. Throws InputError "OPTION 'NAME' is not one of zxing, libdmtx, zbar";
// `option` is how the user gave it ("--reader", a job file's key).
const CodeReader& named_code_reader(std::string_view name, const std::string& option);

}  // namespace mark
