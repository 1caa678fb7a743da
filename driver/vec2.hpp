#pragma once
// A point or vector in the field frame, millimetres. driver/ does not use Eigen; callers convert
// at the boundary (marker/ samples its Figure into these for the quality figures).
#include <cmath>

namespace mark {

struct Vec2 {
  double x = 0;
  double y = 0;
};

inline Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
inline Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
inline Vec2 operator*(double s, Vec2 a) { return {s * a.x, s * a.y}; }
inline double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
// sqrt rather than hypot: field coordinates cannot overflow, and hypot is several times slower
// in the quality loops.
inline double norm(Vec2 a) { return std::sqrt(a.x * a.x + a.y * a.y); }

}  // namespace mark
