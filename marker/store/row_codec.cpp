#include "marker/store/row_codec.hpp"

#include <nlohmann/json.hpp>

namespace mark {

std::string objects_to_json(const std::vector<ObjectText>& objects) {
  nlohmann::json j = nlohmann::json::array();
  for (const ObjectText& o : objects) j.push_back({{"name", o.name}, {"text", o.text}});
  return j.dump();
}

std::vector<ObjectText> objects_from_json(const std::string& text) {
  std::vector<ObjectText> out;
  for (const auto& o : nlohmann::json::parse(text))
    out.push_back({o.at("name").get<std::string>(), o.at("text").get<std::string>()});
  return out;
}

std::string serials_to_json(const std::map<std::string, std::int64_t>& serials) {
  return nlohmann::json(serials).dump();
}

std::map<std::string, std::int64_t> serials_from_json(const std::string& text) {
  return nlohmann::json::parse(text).get<std::map<std::string, std::int64_t>>();
}

}  // namespace mark
