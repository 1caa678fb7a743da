#include "marker/production/part_verdict.hpp"

namespace mark {
namespace {

std::string why_not_read(const CodeVerification& v, std::size_t k) {
  const std::string code = "code " + std::to_string(k + 1);
  const std::string wrong = " (modules wrong: " + std::to_string(v.modules_wrong) + ")";
  if (!v.decoded) return code + " not decoded by " + (v.decided_by.empty() ? "the readers" : v.decided_by) + wrong;
  return code + " read as \"" + v.decoded_data + "\", not \"" + v.expected_data + "\"" + wrong;
}

}  // namespace

std::optional<Rejection> part_verdict(const std::vector<std::vector<CodeVerification>>& codes_per_object) {
  for (std::size_t i = 0; i < codes_per_object.size(); ++i)
    for (std::size_t k = 0; k < codes_per_object[i].size(); ++k)
      if (!codes_per_object[i][k].data_match) return Rejection{i, why_not_read(codes_per_object[i][k], k)};
  return std::nullopt;
}

}  // namespace mark
