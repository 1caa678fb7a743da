#pragma once
// A dose tile the beam has left, kept without its zeros: one 64-bit mask per 64-pixel row says
// which pixels hold dose, and only those values are stored. A stroke's trail covers a few per
// cent of the tiles it crosses, so a 16 KiB tile of floats packs into about 1.5 KiB; a tile
// dense with hatch lines costs at most its 16 KiB plus 640 bytes of masks. Lossless: every
// value reads back exactly.
#include <array>
#include <bit>
#include <cstdint>
#include <span>
#include <vector>

namespace mark {

class PackedTile {
 public:
  static constexpr int kSide = 64;  // pixels per row; one mask word per row

  // From a dense row-major tile of kSide × kSide values.
  explicit PackedTile(std::span<const float> dense) {
    values_.reserve(count_nonzero(dense));
    for (int r = 0; r < kSide; ++r) {
      row_start_[r] = static_cast<std::uint16_t>(values_.size());
      std::uint64_t m = 0;
      for (int c = 0; c < kSide; ++c)
        if (const float v = dense[static_cast<std::size_t>(r * kSide + c)]; v != 0.0f) {
          m |= std::uint64_t{1} << c;
          values_.push_back(v);
        }
      mask_[r] = m;
    }
  }

  // Value of pixel (col, row), 0 where none was stored.
  float value(int col, int row) const {
    const std::uint64_t m = mask_[row];
    if (!((m >> col) & 1)) return 0.0f;
    return values_[row_start_[row] + std::popcount(m & below(col))];
  }
  // Calls f(col, value) for every stored pixel of `row` in columns [c0, c1], left to right.
  template <class F>
  void for_each_in_row(int row, int c0, int c1, F&& f) const {
    const std::uint64_t m = mask_[row];
    std::uint64_t bits = m & ~below(c0) & (c1 + 1 >= kSide ? ~std::uint64_t{0} : below(c1 + 1));
    std::size_t i = row_start_[row] + std::popcount(m & below(c0));
    while (bits) {
      f(std::countr_zero(bits), values_[i++]);
      bits &= bits - 1;
    }
  }
  // Writes every pixel into a dense row-major kSide × kSide tile (zeros included).
  void unpack(std::span<float> dense) const {
    for (int r = 0; r < kSide; ++r) {
      float* row = &dense[static_cast<std::size_t>(r * kSide)];
      for (int c = 0; c < kSide; ++c) row[c] = 0.0f;
      for_each_in_row(r, 0, kSide - 1, [&](int c, float v) { row[c] = v; });
    }
  }
  const std::vector<float>& values() const { return values_; }
  std::size_t bytes() const { return sizeof(*this) + values_.capacity() * sizeof(float); }

 private:
  static std::uint64_t below(int col) { return (std::uint64_t{1} << col) - 1; }  // col < 64
  static std::size_t count_nonzero(std::span<const float> dense) {
    std::size_t n = 0;
    for (float v : dense) n += v != 0.0f;
    return n;
  }

  std::array<std::uint64_t, kSide> mask_;
  std::array<std::uint16_t, kSide> row_start_;  // index in values_ of each row's first value
  std::vector<float> values_;
};

}  // namespace mark
