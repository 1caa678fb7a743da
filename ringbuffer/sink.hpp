#pragma once
// The device interface the drain writes to: a laser scanner (simulated, USB, DAC) or a gravure
// stylus head. The drain calls write() from its own thread at the output rate, one fixed-size
// block at a time; a device that cannot take a block throws, and the drain then halts it.
#include <span>

namespace mark {

template <class T>
class Sink {
 public:
  virtual ~Sink() = default;

  // Output one block of samples, in order, at the device rate (the drain does the pacing).
  // Throw on a device fault (e.g. a coordinate outside the field); the drain then calls halt()
  // and reports the error to whoever joins it.
  virtual void write(std::span<const T> block) = 0;

  // Laser (or stylus) off now and stay off: called on a fault or abort. Must not throw.
  virtual void halt() noexcept = 0;
};

}  // namespace mark
