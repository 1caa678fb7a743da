#pragma once
// The JSON columns of the audit log (objects, serials, figures, issues) and the decoding of one
// audit row from the columns both backends select, in this order (kAuditColumns), so a row
// reads the same from SQLite and PostgreSQL and a damaged cell is one StoreError naming the row.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "marker/store/audit_row.hpp"

namespace mark {

std::string objects_to_json(const std::vector<ObjectText>& objects);
std::vector<ObjectText> objects_from_json(const std::string& text);
std::string serials_to_json(const std::map<std::string, std::int64_t>& serials);
std::map<std::string, std::int64_t> serials_from_json(const std::string& text);

// The columns of an audit row as both backends select them.
enum AuditColumn {
  kColId, kColTime, kColStation, kColJob, kColJobSha, kColKind, kColRemarkOf, kColObjects,
  kColSerials, kColReason, kColNote, kColDataList, kColDataRow, kColOutcomeTime, kColOutcome,
  kColMessage, kColFigures, kColIssues, kAuditColumns
};

// `column(i)` gives column i's text, nothing for NULL. `issues` is a JSON array of
// [counter, period, cycle, value, repeat]. Throws StoreError (damaged) naming `store` and the
// row when a cell does not decode.
AuditRow audit_row_from(const std::function<std::optional<std::string>(int)>& column,
                        const std::string& store);

}  // namespace mark
