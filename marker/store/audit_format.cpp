#include "marker/store/audit_format.hpp"

namespace mark {
namespace {

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string outcome_name(const AuditRow& r) {
  return r.outcome ? std::string(to_string(r.outcome->outcome)) : "pending";
}

}  // namespace

nlohmann::json audit_to_json(const AuditRow& r) {
  nlohmann::json objects = nlohmann::json::array();
  for (const ObjectText& o : r.mark.objects) objects.push_back({{"name", o.name}, {"text", o.text}});
  nlohmann::json j = {{"id", r.id},
                      {"time_utc", r.mark.time_utc},
                      {"station", r.mark.station},
                      {"job", r.mark.job},
                      {"job_sha256", r.mark.job_sha256},
                      {"kind", to_string(r.mark.kind)},
                      {"remark_of", r.mark.remark_of ? nlohmann::json(*r.mark.remark_of) : nlohmann::json()},
                      {"objects", objects},
                      {"text", r.text()},
                      {"serials", r.mark.serials},
                      {"outcome", outcome_name(r)}};
  if (r.outcome) {
    j["outcome_time_utc"] = r.outcome->time_utc;
    j["message"] = r.outcome->message;
    j["figures"] = r.outcome->figures;
  }
  return j;
}

std::string audit_csv_header() {
  return "id,time_utc,station,job,job_sha256,kind,remark_of,text,serials,outcome,outcome_time_utc,"
         "message,figures";
}

std::string audit_to_csv(const AuditRow& r) {
  std::string line = std::to_string(r.id) + "," + csv_field(r.mark.time_utc) + "," +
                     csv_field(r.mark.station) + "," + csv_field(r.mark.job) + "," +
                     r.mark.job_sha256 + "," + std::string(to_string(r.mark.kind)) + "," +
                     (r.mark.remark_of ? std::to_string(*r.mark.remark_of) : "") + "," +
                     csv_field(r.text()) + "," + csv_field(nlohmann::json(r.mark.serials).dump()) +
                     "," + outcome_name(r) + ",";
  if (r.outcome)
    line += csv_field(r.outcome->time_utc) + "," + csv_field(r.outcome->message) + "," +
            csv_field(r.outcome->figures.dump());
  else
    line += ",,";
  return line;
}

std::string audit_to_line(const AuditRow& r) {
  std::string text = r.text();
  for (char& c : text)
    if (c == '\n') c = '|';
  std::string line = std::to_string(r.id) + "  " + r.mark.time_utc + "  " + r.mark.station + "  " +
                     std::string(to_string(r.mark.kind)) + "  " + outcome_name(r) + "  " + text;
  for (const auto& [name, value] : r.mark.serials) line += "  " + name + "=" + std::to_string(value);
  if (r.mark.remark_of) line += "  (re-mark of " + std::to_string(*r.mark.remark_of) + ")";
  if (r.outcome && !r.outcome->message.empty()) line += "  — " + r.outcome->message;
  return line;
}

}  // namespace mark
