#pragma once
// An encoded symbol as its modules: rows × columns of dark or light, row 0 at the top (as a
// reader sees it), column 0 at the left. A linear code (Code 128) is one row of bar modules.
#include <cstdint>
#include <vector>

#include "marker/codes/symbology.hpp"

namespace mark {

struct ModuleMatrix {
  Symbology symbology = Symbology::datamatrix;
  int rows = 0;
  int cols = 0;
  std::vector<std::uint8_t> modules;  // rows × cols, 1 = dark

  bool dark(int row, int col) const {
    return modules[static_cast<std::size_t>(row) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(col)] != 0;
  }
  std::size_t dark_count() const;
};

}  // namespace mark
