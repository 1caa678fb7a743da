#pragma once
// What to encode: the symbology, the data (bytes; GS1 codes take "(01)…(17)…" text) and the
// symbology's own choices — Data Matrix size and shape, QR error-correction level and version.
#include <string>
#include <string_view>

#include "marker/codes/module_matrix.hpp"
#include "marker/codes/symbology.hpp"

namespace mark {

enum class MatrixShape { square, rectangular, any };

struct CodeSpec {
  Symbology symbology = Symbology::datamatrix;
  std::string data;
  // Data Matrix ECC 200: a fixed size (rows × columns, e.g. 16 × 16 or 16 × 48), or 0 × 0 for the
  // smallest symbol of the shape that holds the data. Square is what DPM marks mostly use.
  int matrix_rows = 0;
  int matrix_cols = 0;
  MatrixShape shape = MatrixShape::square;
  // QR: error-correction level L, M, Q or H, and a fixed version 1–40 (0: the smallest).
  char qr_ecc = 'M';
  int qr_version = 0;
};

std::string_view to_string(MatrixShape shape);
MatrixShape parse_matrix_shape(std::string_view name);  // square, rectangular, any
// "16x16", "16x48" (rows × columns); throws InputError naming the value.
void parse_matrix_size(std::string_view text, int& rows, int& cols);

// The bytes a reader should return: the data itself, or for GS1 codes the element string with
// GS separators (gs1_text.hpp).
std::string expected_decoded_data(const CodeSpec& spec);

// Encodes with zint. Throws InputError with zint's reason when the data cannot be encoded (too
// long for a fixed size, invalid GS1 data or check digit, characters Code 128 cannot carry).
ModuleMatrix encode_code(const CodeSpec& spec);

// The Data Matrix ECC 200 sizes (ISO/IEC 16022 square 10 × 10 … 144 × 144 and rectangular
// 8 × 18 … 16 × 48), in zint's size-index order.
struct MatrixSize {
  int rows;
  int cols;
};
const std::vector<MatrixSize>& datamatrix_sizes();

}  // namespace mark
