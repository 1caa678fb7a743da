#include "marker/store/audit_row.hpp"

#include "marker/store/store_error.hpp"

namespace mark {

std::string_view to_string(Outcome o) {
  switch (o) {
    case Outcome::done: return "done";
    case Outcome::aborted: return "aborted";
    case Outcome::failed: return "failed";
    case Outcome::reserved: return "reserved";
    case Outcome::rejected: return "rejected";
  }
  return "?";
}

std::optional<Outcome> parse_outcome(std::string_view name) {
  for (Outcome o : {Outcome::done, Outcome::aborted, Outcome::failed, Outcome::reserved, Outcome::rejected})
    if (name == to_string(o)) return o;
  return std::nullopt;
}

std::string_view to_string(AuditKind k) {
  switch (k) {
    case AuditKind::mark: return "mark";
    case AuditKind::remark: return "remark";
    case AuditKind::reserve: return "reserve";
    case AuditKind::set: return "set";
    case AuditKind::create: return "create";
  }
  return "?";
}

std::optional<AuditKind> parse_audit_kind(std::string_view name) {
  for (AuditKind k : {AuditKind::mark, AuditKind::remark, AuditKind::reserve, AuditKind::set,
                     AuditKind::create})
    if (name == to_string(k)) return k;
  return std::nullopt;
}

std::string_view to_string(StoreErrorKind kind) {
  switch (kind) {
    case StoreErrorKind::busy: return "locked";
    case StoreErrorKind::full: return "full";
    case StoreErrorKind::io: return "i/o error";
    case StoreErrorKind::connection: return "connection lost";
    case StoreErrorKind::corrupt: return "damaged";
    case StoreErrorKind::constraint: return "refused by a key";
    case StoreErrorKind::cancelled: return "cancelled";
    case StoreErrorKind::missing: return "missing";
    case StoreErrorKind::other: return "error";
  }
  return "?";
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
