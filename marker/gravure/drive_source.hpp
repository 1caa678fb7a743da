#pragma once
// A stream of stylus drive values at the stylus clock, before the tuning filters: the toolpath
// of an image (stylus_toolpath.hpp) or the head response test pattern (head_response.hpp).
#include <cstdint>
#include <span>

namespace mark {

class DriveSource {
 public:
  virtual ~DriveSource() = default;
  virtual std::uint64_t total_samples() const = 0;
  // The next values (µm below the surface), up to out.size(); 0 at the end.
  virtual std::size_t next(std::span<double> out) = 0;
};

}  // namespace mark
