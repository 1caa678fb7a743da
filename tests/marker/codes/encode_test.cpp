// Encoding through zint: the Data Matrix size table is zint's own, capacities match the
// published ones (dynamics.md §5.4), shapes and fixed sizes are honoured, QR levels and
// versions change the symbol as the standard says, GS1 text becomes the element string a
// reader returns, and bad data is refused with the reason.
#include <gtest/gtest.h>

#include <string>

#include "base/error.hpp"
#include "marker/codes/code_data.hpp"
#include "marker/codes/code_spec.hpp"
#include "marker/codes/gs1_text.hpp"

namespace mark {
namespace {

ModuleMatrix dm(const std::string& data, int rows = 0, int cols = 0, MatrixShape shape = MatrixShape::square) {
  CodeSpec s;
  s.data = data;
  s.matrix_rows = rows;
  s.matrix_cols = cols;
  s.shape = shape;
  return encode_code(s);
}

std::string error_of(const CodeSpec& s) {
  try {
    encode_code(s);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Encode, EveryDataMatrixSizeOfTheTableComesOutOfZintAsListed) {
  for (const MatrixSize& size : datamatrix_sizes()) {
    const ModuleMatrix m = dm("1", size.rows, size.cols);
    EXPECT_EQ(m.rows, size.rows);
    EXPECT_EQ(m.cols, size.cols);
  }
}

TEST(Encode, DataMatrixCapacitiesMatchThePublishedOnes) {
  // ECC 200 capacities (numeric / alphanumeric / bytes): 10×10 6/3/1, 12×12 10/6/3,
  // 16×16 24/16/10, 18×18 36/25/16, 24×24 72/52/34, 8×18 10/6/3, 16×48 98/72/47.
  struct Cap {
    int rows, cols, numeric, alnum, bytes;
  };
  for (const Cap c : {Cap{10, 10, 6, 3, 1}, Cap{12, 12, 10, 6, 3}, Cap{16, 16, 24, 16, 10},
                      Cap{18, 18, 36, 25, 16}, Cap{24, 24, 72, 52, 34}, Cap{8, 18, 10, 6, 3},
                      Cap{16, 48, 98, 72, 47}}) {
    SCOPED_TRACE(std::to_string(c.rows) + "x" + std::to_string(c.cols));
    EXPECT_NO_THROW(dm(std::string(c.numeric, '7'), c.rows, c.cols));
    EXPECT_THROW(dm(std::string(c.numeric + 1, '7'), c.rows, c.cols), InputError);
    // Alphanumeric capacity is for upper-case text (C40 encodation).
    EXPECT_NO_THROW(dm(std::string(c.alnum, 'Q'), c.rows, c.cols));
    EXPECT_THROW(dm(std::string(c.alnum + 1, 'Q'), c.rows, c.cols), InputError);
    EXPECT_NO_THROW(dm(std::string(c.bytes, '\xE9'), c.rows, c.cols));
    EXPECT_THROW(dm(std::string(c.bytes + 1, '\xE9'), c.rows, c.cols), InputError);
  }
}

TEST(Encode, AutomaticSizeIsTheSmallestOfTheShape) {
  EXPECT_EQ(dm("123456").rows, 10);
  EXPECT_EQ(dm("1234567").rows, 12);
  const std::string text = "SN 0042 LOT 7 A";
  const ModuleMatrix rect = dm(text, 0, 0, MatrixShape::rectangular);
  EXPECT_LT(rect.rows, rect.cols);
  // Every smaller rectangular size refuses the data.
  bool smaller = true;
  for (const MatrixSize& s : datamatrix_sizes()) {
    if (s.rows >= s.cols) continue;
    if (s.rows == rect.rows && s.cols == rect.cols) smaller = false;
    if (smaller) {
      EXPECT_THROW(dm(text, s.rows, s.cols), InputError) << s.rows << "x" << s.cols;
    }
  }
  EXPECT_FALSE(smaller);
  const ModuleMatrix any = dm("1234567890", 0, 0, MatrixShape::any);
  EXPECT_EQ(any.rows * any.cols, 8 * 18);  // smaller than the square 12×12
}

TEST(Encode, QrLevelAndVersionSizeTheSymbol) {
  CodeSpec s;
  s.symbology = Symbology::qr;
  s.data = "SN 2026-000123 LOT 42";
  s.qr_ecc = 'L';
  const ModuleMatrix low = encode_code(s);
  s.qr_ecc = 'H';
  const ModuleMatrix high = encode_code(s);
  // 21 alphanumeric characters: version 1 holds 25 at level L; at level H version 2 holds 20,
  // version 3 holds 35 (ISO/IEC 18004 capacity table).
  EXPECT_EQ(low.rows, 21);
  EXPECT_EQ(high.rows, 29);
  s.qr_version = 5;
  EXPECT_EQ(encode_code(s).rows, 21 + 4 * 4);
  s.qr_ecc = 'X';
  EXPECT_EQ(error_of(s), "QR error-correction level 'X' is not one of L, M, Q, H");
}

TEST(Encode, Code128IsOneRowOfBarModules) {
  CodeSpec s;
  s.symbology = Symbology::code128;
  s.data = "SN-0042abc";
  const ModuleMatrix m = encode_code(s);
  EXPECT_EQ(m.rows, 1);
  // Start, 10 characters in code set B, check, stop: 11 modules each, stop 13.
  EXPECT_EQ(m.cols, 11 * 12 + 13);
  EXPECT_TRUE(m.dark(0, 0));
  EXPECT_TRUE(m.dark(0, m.cols - 1));
}

TEST(Encode, Gs1TextBecomesTheElementStringAReaderReturns) {
  const std::vector<Gs1Field> f = parse_gs1_text("(01)09506000134352(17)261231(10)LOT42(21)SN0001");
  ASSERT_EQ(f.size(), 4u);
  EXPECT_EQ(f[2].ai, "10");
  EXPECT_EQ(f[2].data, "LOT42");
  // (01) and (17) have predefined lengths; (10) is variable and not last: GS after it.
  EXPECT_EQ(gs1_element_string(f), "01095060001343521726123110LOT42\x1d" "21SN0001");
  EXPECT_EQ(gs1_element_string(parse_gs1_text("[01]09506000134352[21]A1[10]B2")),
            "0109506000134352" "21A1\x1d" "10B2");
  CodeSpec s;
  s.symbology = Symbology::gs1_datamatrix;
  s.data = "(01)09506000134352(17)261231(10)LOT42(21)SN0001";
  EXPECT_EQ(expected_decoded_data(s), gs1_element_string(f));
  EXPECT_NO_THROW(encode_code(s));
}

TEST(Encode, BadGs1IsRefusedWithTheReason) {
  CodeSpec s;
  s.symbology = Symbology::gs1_datamatrix;
  s.data = "(01)09506000134353";  // wrong check digit: zint only warns, we refuse
  EXPECT_NE(error_of(s).find("gs1-datamatrix: cannot encode the data"), std::string::npos) << error_of(s);
  EXPECT_NE(error_of(s).find("checksum"), std::string::npos) << error_of(s);
  s.data = "(01)09506000134352(17)261399";  // no month 13
  EXPECT_NE(error_of(s).find("Invalid month"), std::string::npos) << error_of(s);
  s.data = "(01)0950600013435";  // 13 digits
  EXPECT_NE(error_of(s).find("Invalid data length for AI (01)"), std::string::npos) << error_of(s);
  s.data = "01)0950";
  EXPECT_EQ(error_of(s), "GS1 data '01)0950', character 1: expected '(' or '[' before the first AI");
  s.data = "(01)";
  EXPECT_EQ(error_of(s), "GS1 data '(01)', character 5: AI (01) has no data");
  s.data = "(1)5";
  EXPECT_EQ(error_of(s), "GS1 data '(1)5', character 2: AI '1' is not 2 to 4 digits");
  s.data = "(10)AB(21";
  EXPECT_EQ(error_of(s), "GS1 data '(10)AB(21', character 7: no ')' after the AI");
}

TEST(Encode, ImpossibleRequestsAreRefused) {
  CodeSpec s;
  s.data = "";
  EXPECT_EQ(error_of(s), "datamatrix: the data is empty");
  s.data = std::string(30, 'A');
  s.matrix_rows = s.matrix_cols = 10;
  EXPECT_NE(error_of(s).find("datamatrix 10x10: cannot encode the data"), std::string::npos) << error_of(s);
  s.matrix_rows = 11;
  s.matrix_cols = 11;
  EXPECT_NE(error_of(s).find("11x11 is not an ECC 200 size"), std::string::npos);
  s.matrix_rows = s.matrix_cols = 0;
  s.data = std::string(5000, '1');
  EXPECT_NE(error_of(s).find("5000 bytes"), std::string::npos);
  int r = 0, c = 0;
  EXPECT_THROW(parse_matrix_size("16", r, c), InputError);
  EXPECT_THROW(parse_matrix_size("16x", r, c), InputError);
  EXPECT_THROW(parse_matrix_size("x16", r, c), InputError);
  EXPECT_THROW(parse_matrix_size("16x1a", r, c), InputError);
  parse_matrix_size("16x48", r, c);
  EXPECT_EQ(r, 16);
  EXPECT_EQ(c, 48);
}

TEST(CodeData, EscapesGiveTheControlCharactersOfDpmFormats) {
  EXPECT_EQ(unescape_code_data("[)>\\R06\\GSN123\\R\\E"), "[)>\x1e" "06\x1dSN123\x1e\x04");
  EXPECT_EQ(unescape_code_data("a\\\\b\\x41\\n"), "a\\bA\n");
  EXPECT_EQ(unescape_code_data("no escapes"), "no escapes");
  const auto error = [](const char* t) {
    try {
      unescape_code_data(t);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error("ab\\q").substr(0, 41), "code data, character 4: unknown escape \\q");
  EXPECT_NE(error("\\x4").find("two hex digits"), std::string::npos);
  EXPECT_NE(error("end\\").find("a backslash ends the data"), std::string::npos);
  EXPECT_EQ(printable_bytes(std::string("A\x1d\\é")), "A\\x1D\\\\é");
}

}  // namespace
}  // namespace mark
