// How GoogleTest prints the engine's types that parameterise tests: by name, not as a byte dump
// in every CTest log line ("208-byte object <D0-56 …>").
#pragma once

#include <ostream>

#include "marker/codes/code_spec.hpp"
#include "marker/plan/pen.hpp"

namespace mark {

inline void PrintTo(const MatrixSize& s, std::ostream* os) { *os << s.rows << "x" << s.cols; }
inline void PrintTo(CornerStrategy s, std::ostream* os) { *os << to_string(s); }

}  // namespace mark
