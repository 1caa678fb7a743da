#pragma once
// A device refused or failed: a sample outside its field, a write after halt, an I/O fault.
// The message names the device and the offending value.
#include <stdexcept>

namespace mark {

class DeviceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace mark
