#include "driver/sim/quality_class.hpp"

namespace mark {

std::string_view to_string(QualityClass c) {
  switch (c) {
    case QualityClass::poor: return "poor";
    case QualityClass::good: return "good";
    case QualityClass::high: return "high";
  }
  return "?";
}

std::optional<QualityClass> parse_quality_class(std::string_view name) {
  for (QualityClass c : {QualityClass::poor, QualityClass::good, QualityClass::high})
    if (name == to_string(c)) return c;
  return std::nullopt;
}

}  // namespace mark
