#pragma once
// The JSON columns of the audit log (objects, serials, figures), shared by both backends.
#include <map>
#include <string>
#include <vector>

#include "marker/store/audit_row.hpp"

namespace mark {

std::string objects_to_json(const std::vector<ObjectText>& objects);
std::vector<ObjectText> objects_from_json(const std::string& text);
std::string serials_to_json(const std::map<std::string, std::int64_t>& serials);
std::map<std::string, std::int64_t> serials_from_json(const std::string& text);

}  // namespace mark
