#pragma once
// π once for the whole engine: each file declaring its own kPi collided in the unity build.
#include <numbers>

namespace mark {

inline constexpr double kPi = std::numbers::pi;

}  // namespace mark
