// zint does the encoding (Reed–Solomon, mode switching, GS1 validation); this only chooses its
// options and reads the modules back.
#include <zint.h>

#include <algorithm>
#include <memory>
#include <string>

#include "base/error.hpp"
#include "marker/codes/code_spec.hpp"
#include "marker/codes/gs1_text.hpp"

namespace mark {
namespace {

struct SymbolDeleter {
  void operator()(zint_symbol* s) const { ZBarcode_Delete(s); }
};
using SymbolPtr = std::unique_ptr<zint_symbol, SymbolDeleter>;

// zint 2.11 keeps one bit per module in encoded_data, least significant bit first.
bool module_set(const zint_symbol& s, int row, int col) {
  return ((s.encoded_data[row][col >> 3] >> (col & 7)) & 1) != 0;
}

int zint_symbology(Symbology s) {
  switch (s) {
    case Symbology::datamatrix:
    case Symbology::gs1_datamatrix: return BARCODE_DATAMATRIX;
    case Symbology::qr: return BARCODE_QRCODE;
    case Symbology::code128: return BARCODE_CODE128;
    case Symbology::gs1_128: return BARCODE_GS1_128;
  }
  return BARCODE_DATAMATRIX;
}

// One zint run with the given size option; returns zint's result code, the symbol in `out`.
int run_zint(const CodeSpec& spec, int size_option, int shape_option, SymbolPtr& out) {
  out.reset(ZBarcode_Create());
  if (!out) throw std::bad_alloc();
  zint_symbol& s = *out;
  s.symbology = zint_symbology(spec.symbology);
  s.input_mode = DATA_MODE;
  if (is_gs1(spec.symbology)) s.input_mode = GS1_MODE | (spec.data.front() == '(' ? GS1PARENS_MODE : 0);
  if (spec.symbology == Symbology::qr) {
    s.option_1 = static_cast<int>(std::string_view("LMQH").find(spec.qr_ecc)) + 1;
    s.option_2 = spec.qr_version;
  } else if (!is_linear(spec.symbology)) {
    s.option_2 = size_option;
    s.option_3 = shape_option;
  }
  s.output_options = BARCODE_NO_QUIET_ZONES;
  s.show_hrt = 0;
  // zint only warns about a GS1 check digit or date it finds wrong and encodes anyway; a part
  // marked with a non-compliant UDI is scrap, so every warning refuses.
  s.warn_level = WARN_FAIL_ALL;
  return ZBarcode_Encode(&s, reinterpret_cast<const unsigned char*>(spec.data.data()),
                         static_cast<int>(spec.data.size()));
}

std::string describe(const CodeSpec& spec) {
  std::string d = std::string(to_string(spec.symbology));
  if (spec.matrix_rows > 0) d += " " + std::to_string(spec.matrix_rows) + "x" + std::to_string(spec.matrix_cols);
  if (spec.symbology == Symbology::qr) {
    d += std::string(" level ") + spec.qr_ecc;
    if (spec.qr_version > 0) d += " version " + std::to_string(spec.qr_version);
  }
  return d;
}

void check_spec(const CodeSpec& spec) {
  if (spec.data.empty()) throw InputError(std::string(to_string(spec.symbology)) + ": the data is empty");
  if (spec.data.size() > 4000)
    throw InputError(std::string(to_string(spec.symbology)) + ": " + std::to_string(spec.data.size()) +
                     " bytes of data, more than any symbol holds (at most 4000)");
  if (is_gs1(spec.symbology)) parse_gs1_text(spec.data);  // our message names the position
  if (spec.symbology == Symbology::qr) {
    if (std::string_view("LMQH").find(spec.qr_ecc) == std::string_view::npos)
      throw InputError(std::string("QR error-correction level '") + spec.qr_ecc + "' is not one of L, M, Q, H");
    if (spec.qr_version < 0 || spec.qr_version > 40)
      throw InputError("QR version " + std::to_string(spec.qr_version) + " is outside 1 .. 40 (0: automatic)");
  }
}

}  // namespace

const std::vector<MatrixSize>& datamatrix_sizes() {
  static const std::vector<MatrixSize> sizes = {
      {10, 10},   {12, 12},   {14, 14},   {16, 16},   {18, 18},   {20, 20},   {22, 22},   {24, 24},
      {26, 26},   {32, 32},   {36, 36},   {40, 40},   {44, 44},   {48, 48},   {52, 52},   {64, 64},
      {72, 72},   {80, 80},   {88, 88},   {96, 96},   {104, 104}, {120, 120}, {132, 132}, {144, 144},
      {8, 18},    {8, 32},    {12, 26},   {12, 36},   {16, 36},   {16, 48}};
  return sizes;
}

std::string expected_decoded_data(const CodeSpec& spec) {
  return is_gs1(spec.symbology) ? gs1_element_string(parse_gs1_text(spec.data)) : spec.data;
}

ModuleMatrix encode_code(const CodeSpec& spec) {
  check_spec(spec);
  const bool matrix = spec.symbology == Symbology::datamatrix || spec.symbology == Symbology::gs1_datamatrix;
  // Size options to try in turn: the fixed size, or zint's automatic choice for a shape, or
  // (rectangular only, which zint cannot restrict itself to) every rectangular size upward.
  std::vector<std::pair<int, int>> attempts;  // (size index, shape option)
  const auto& sizes = datamatrix_sizes();
  if (matrix && spec.matrix_rows > 0) {
    const auto it = std::find_if(sizes.begin(), sizes.end(), [&](const MatrixSize& s) {
      return s.rows == spec.matrix_rows && s.cols == spec.matrix_cols;
    });
    if (it == sizes.end())
      throw InputError("Data Matrix size " + std::to_string(spec.matrix_rows) + "x" +
                       std::to_string(spec.matrix_cols) +
                       " is not an ECC 200 size (square 10x10 .. 144x144, rectangular 8x18, 8x32, "
                       "12x26, 12x36, 16x36, 16x48)");
    attempts.emplace_back(static_cast<int>(it - sizes.begin()) + 1, 0);
  } else if (matrix && spec.shape == MatrixShape::rectangular) {
    for (int k = 25; k <= 30; ++k) attempts.emplace_back(k, 0);
  } else {
    attempts.emplace_back(0, matrix && spec.shape == MatrixShape::square ? DM_SQUARE : 0);
  }
  SymbolPtr symbol;
  int code = 0;
  for (const auto& [size, shape] : attempts) {
    code = run_zint(spec, size, shape, symbol);
    if (code < ZINT_ERROR) break;
  }
  if (code >= ZINT_ERROR)
    throw InputError(describe(spec) + ": cannot encode the data: " + std::string(symbol->errtxt));
  ModuleMatrix m;
  m.symbology = spec.symbology;
  m.rows = is_linear(spec.symbology) ? 1 : symbol->rows;
  m.cols = symbol->width;
  m.modules.resize(static_cast<std::size_t>(m.rows) * static_cast<std::size_t>(m.cols));
  for (int r = 0; r < m.rows; ++r)
    for (int c = 0; c < m.cols; ++c)
      m.modules[static_cast<std::size_t>(r) * static_cast<std::size_t>(m.cols) + static_cast<std::size_t>(c)] =
          module_set(*symbol, r, c);
  return m;
}

std::size_t ModuleMatrix::dark_count() const {
  return static_cast<std::size_t>(std::count(modules.begin(), modules.end(), 1));
}

std::string_view to_string(MatrixShape s) {
  return s == MatrixShape::square ? "square" : s == MatrixShape::rectangular ? "rectangular" : "any";
}

MatrixShape parse_matrix_shape(std::string_view name) {
  if (name == "square") return MatrixShape::square;
  if (name == "rectangular") return MatrixShape::rectangular;
  if (name == "any") return MatrixShape::any;
  throw InputError("Data Matrix shape '" + std::string(name) + "' is not one of square, rectangular, any");
}

void parse_matrix_size(std::string_view text, int& rows, int& cols) {
  const auto fail = [&] {
    throw InputError("Data Matrix size '" + std::string(text) + "': expected ROWSxCOLUMNS such as 16x16 or 16x48");
  };
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string_view::npos || x == 0 || x + 1 >= text.size() || x > 3 || text.size() - x - 1 > 3) fail();
  int v[2] = {0, 0};
  for (int k = 0; k < 2; ++k) {
    const std::string_view part = k == 0 ? text.substr(0, x) : text.substr(x + 1);
    for (char c : part) {
      if (c < '0' || c > '9') fail();
      v[k] = v[k] * 10 + (c - '0');
    }
  }
  rows = v[0];
  cols = v[1];
}

}  // namespace mark
