#pragma once
// The audit log for scripts: one JSON object per row (JSON Lines) or CSV (RFC 4180), fields
// named in docs/store.md. `text`, `serials` and `outcome` are the same as in `mark --json`.
#include <nlohmann/json.hpp>
#include <string>

#include "marker/store/audit_row.hpp"

namespace mark {

nlohmann::json audit_to_json(const AuditRow& row);
std::string audit_csv_header();
std::string audit_to_csv(const AuditRow& row);
// One human line: "17  2026-03-05T09:41:00.000000Z  st1  mark  done  SN 000042  sn=42".
std::string audit_to_line(const AuditRow& row);

}  // namespace mark
