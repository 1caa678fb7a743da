#include "ringbuffer/drain_stats.hpp"

namespace mark {

const char* to_string(DrainEnd end) {
  switch (end) {
    case DrainEnd::completed: return "completed";
    case DrainEnd::cancelled: return "cancelled";
    case DrainEnd::underrun: return "underrun";
    case DrainEnd::device_fault: return "device_fault";
  }
  return "?";
}

}  // namespace mark
