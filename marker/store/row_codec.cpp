#include "marker/store/row_codec.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "marker/store/store_error.hpp"

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

AuditRow audit_row_from(const std::function<std::optional<std::string>(int)>& column,
                        const std::string& store) {
  AuditRow r;
  const auto text = [&](int c) { return column(c).value_or(""); };
  const auto integer = [&](int c) -> std::optional<std::int64_t> {
    const auto v = column(c);
    if (!v) return std::nullopt;
    return std::stoll(*v);
  };
  try {
    r.id = integer(kColId).value_or(0);
    r.mark.time_utc = text(kColTime);
    r.mark.station = text(kColStation);
    r.mark.job = text(kColJob);
    r.mark.job_sha256 = text(kColJobSha);
    const std::string kind = text(kColKind);
    const auto k = parse_audit_kind(kind);
    if (!k) throw std::runtime_error("kind '" + kind + "'");
    r.mark.kind = *k;
    r.mark.remark_of = integer(kColRemarkOf);
    r.mark.objects = objects_from_json(text(kColObjects));
    r.mark.serials = serials_from_json(text(kColSerials));
    r.mark.reason = text(kColReason);
    r.mark.note = text(kColNote);
    r.mark.data_list = text(kColDataList);
    r.mark.data_row = integer(kColDataRow);
    if (const auto outcome = column(kColOutcome)) {
      OutcomeRecord o;
      o.time_utc = text(kColOutcomeTime);
      const auto parsed = parse_outcome(*outcome);
      if (!parsed) throw std::runtime_error("outcome '" + *outcome + "'");
      o.outcome = *parsed;
      o.message = text(kColMessage);
      o.figures = nlohmann::json::parse(text(kColFigures));
      r.outcome = std::move(o);
    }
    if (const auto issues = column(kColIssues)) {
      for (const auto& i : nlohmann::json::parse(*issues)) {
        if (i.is_null()) continue;
        r.issues.push_back({i.at(0).get<std::string>(), i.at(3).get<std::int64_t>(),
                            i.at(4).get<std::int64_t>(), i.at(1).get<std::string>(),
                            i.at(2).get<std::int64_t>()});
      }
      std::sort(r.issues.begin(), r.issues.end(),
                [](const Issue& a, const Issue& b) { return a.counter < b.counter; });
    }
  } catch (const std::exception& e) {
    throw StoreError("serial store " + store + ": audit row " + text(kColId) +
                         " does not decode (" + e.what() +
                         "): the store is damaged, see `marker store check`",
                     StoreErrorKind::corrupt);
  }
  return r;
}

}  // namespace mark
