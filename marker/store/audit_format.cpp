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

// Each value with the period and cycle it was issued in: 7 in cycle 1 is not the 7 of cycle 0.
nlohmann::json values_json(const AuditRow& r) {
  nlohmann::json v = nlohmann::json::array();
  for (const Issue& i : r.issues)
    v.push_back({{"counter", i.counter}, {"value", i.value}, {"period", i.period}, {"cycle", i.cycle},
                 {"repeat", i.repeat}});
  return v;
}

nlohmann::json data_row_json(const AuditRow& r) {
  if (!r.mark.data_row) return nullptr;
  return {{"list", r.mark.data_list}, {"row", *r.mark.data_row}};
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
                      {"values", values_json(r)},
                      {"data_row", data_row_json(r)},
                      {"reason", r.mark.reason},
                      {"note", r.mark.note},
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
         "message,figures,values,data_list,data_row,reason,note";
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
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on a chain starting with ",".
  line.append(",").append(csv_field(values_json(r).dump()));
  line.append(",").append(csv_field(r.mark.data_list));
  line.append(",").append(r.mark.data_row ? std::to_string(*r.mark.data_row) : "");
  line.append(",").append(csv_field(r.mark.reason));
  line.append(",").append(csv_field(r.mark.note));
  return line;
}

std::string audit_to_line(const AuditRow& r) {
  std::string text = r.text();
  for (char& c : text)
    if (c == '\n') c = '|';
  std::string line = std::to_string(r.id) + "  " + r.mark.time_utc + "  " + r.mark.station + "  " +
                     std::string(to_string(r.mark.kind)) + "  " + outcome_name(r) + "  " + text;
  for (const auto& [name, value] : r.mark.serials) line += "  " + name + "=" + std::to_string(value);
  if (r.mark.data_row) line += "  " + r.mark.data_list + " row " + std::to_string(*r.mark.data_row);
  if (r.mark.remark_of) line += "  (re-mark of " + std::to_string(*r.mark.remark_of) + ")";
  if (!r.mark.reason.empty()) line += "  reason: " + r.mark.reason;
  if (!r.mark.note.empty()) line += "  note: " + r.mark.note;
  if (r.outcome && !r.outcome->message.empty()) line += "  — " + r.outcome->message;
  return line;
}

}  // namespace mark
