#pragma once
// The usual visitor helper for std::visit over element geometry.
namespace mark {
template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;
}  // namespace mark
