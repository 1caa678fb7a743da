#include "marker/store/audit_row.hpp"

namespace mark {

std::string_view to_string(Outcome o) {
  switch (o) {
    case Outcome::done: return "done";
    case Outcome::aborted: return "aborted";
    case Outcome::failed: return "failed";
    case Outcome::reserved: return "reserved";
  }
  return "?";
}

std::optional<Outcome> parse_outcome(std::string_view name) {
  for (Outcome o : {Outcome::done, Outcome::aborted, Outcome::failed, Outcome::reserved})
    if (name == to_string(o)) return o;
  return std::nullopt;
}

std::string_view to_string(AuditKind k) {
  switch (k) {
    case AuditKind::mark: return "mark";
    case AuditKind::remark: return "remark";
    case AuditKind::reserve: return "reserve";
    case AuditKind::set: return "set";
  }
  return "?";
}

std::optional<AuditKind> parse_audit_kind(std::string_view name) {
  for (AuditKind k : {AuditKind::mark, AuditKind::remark, AuditKind::reserve, AuditKind::set})
    if (name == to_string(k)) return k;
  return std::nullopt;
}

std::string AuditRow::text() const {
  std::string t;
  for (std::size_t i = 0; i < mark.objects.size(); ++i) {
    if (i) t += '\n';
    t += mark.objects[i].text;
  }
  return t;
}

}  // namespace mark
