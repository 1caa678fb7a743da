// libFuzzer target for the parsers of code data we wrote ourselves — escapes, GS1 text, Data
// Matrix sizes — and for the encoder wrapper around zint fed whatever they accept. The first
// byte chooses the path. A parser either throws InputError or returns something that keeps its
// invariants; the encoder either refuses with InputError or returns a matrix of the size it
// says. Anything else (a crash, a sanitizer report, another exception) is a bug.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "base/error.hpp"
#include "marker/codes/code_data.hpp"
#include "marker/codes/code_spec.hpp"
#include "marker/codes/gs1_text.hpp"

namespace {

[[noreturn]] void broken(const char* what) {
  std::fprintf(stderr, "fuzz invariant broken: %s\n", what);
  std::abort();
}

void check_matrix(const mark::ModuleMatrix& m) {
  if (m.rows <= 0 || m.cols <= 0) broken("an empty symbol was returned");
  if (m.modules.size() != static_cast<std::size_t>(m.rows) * static_cast<std::size_t>(m.cols))
    broken("module count differs from rows × cols");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    switch (data[0] % 6) {
      case 0: {
        const std::string bytes = mark::unescape_code_data(text);
        if (bytes.size() > text.size()) broken("unescaping made the data longer");
        mark::printable_bytes(bytes);
        break;
      }
      case 1: {
        const auto fields = mark::parse_gs1_text(text);
        if (fields.empty()) broken("GS1 text parsed to no fields");
        for (const auto& f : fields)
          if (f.ai.size() < 2 || f.ai.size() > 4 || f.data.empty()) broken("a GS1 field outside its shape");
        const std::string element = mark::gs1_element_string(fields);
        if (element.size() > text.size()) broken("element string longer than its text");
        break;
      }
      case 2: {
        int rows = 0, cols = 0;
        mark::parse_matrix_size(text, rows, cols);
        if (rows < 0 || cols < 0 || rows > 999 || cols > 999) broken("matrix size out of its digits");
        break;
      }
      default: {
        if (text.size() > 300) return 0;  // zint's own limits are zint's business; keep runs fast
        mark::CodeSpec spec;
        static const mark::Symbology kinds[] = {mark::Symbology::datamatrix, mark::Symbology::gs1_datamatrix,
                                                mark::Symbology::qr, mark::Symbology::code128,
                                                mark::Symbology::gs1_128};
        spec.symbology = kinds[(data[0] / 6) % 5];
        spec.data = std::string(text);
        spec.shape = static_cast<mark::MatrixShape>((data[0] / 30) % 3);
        check_matrix(mark::encode_code(spec));
        if (mark::expected_decoded_data(spec).empty()) broken("a symbol that should decode to nothing");
        break;
      }
    }
  } catch (const mark::InputError&) {
  }
  return 0;
}
