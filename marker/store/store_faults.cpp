#include "marker/store/store_faults.hpp"

namespace mark {

std::string_view to_string(StoreStep s) { return s == StoreStep::allocate ? "allocate" : "outcome"; }

std::string_view to_string(StoreFaultKind k) {
  switch (k) {
    case StoreFaultKind::locked: return "locked";
    case StoreFaultKind::full: return "full";
    case StoreFaultKind::io: return "io";
    case StoreFaultKind::stopped: return "stopped";
  }
  return "?";
}

std::optional<StoreStep> parse_store_step(std::string_view name) {
  for (StoreStep s : {StoreStep::allocate, StoreStep::outcome})
    if (name == to_string(s)) return s;
  return std::nullopt;
}

std::optional<StoreFaultKind> parse_store_fault(std::string_view name) {
  for (StoreFaultKind k : {StoreFaultKind::locked, StoreFaultKind::full, StoreFaultKind::io,
                           StoreFaultKind::stopped})
    if (name == to_string(k)) return k;
  return std::nullopt;
}

}  // namespace mark
