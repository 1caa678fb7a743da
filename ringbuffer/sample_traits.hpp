#pragma once
// Every sample type the line memory and drain carry declares its safe sample next to itself:
//
//   T safe_sample(const T& last);   // found by argument-dependent lookup
//
// the sample the drain emits on an underrun, on abort and after the end of a job: the laser
// off (holding the last position, so the mirrors do not jump), the gravure stylus lifted clear
// of the cylinder. There is deliberately no default: repeating the last sample would keep a
// laser burning or a stylus cutting. A sample type without one does not compile in a drain.
#include <concepts>

namespace mark {

template <class T>
concept HasSafeSample = requires(const T& last) {
  { safe_sample(last) } -> std::convertible_to<T>;
};

}  // namespace mark
