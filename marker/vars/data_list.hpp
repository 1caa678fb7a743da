#pragma once
// A data list: the rows of a CSV file (RFC 4180) a production job takes one per part, in file
// order, through {col:NAME} fields — EzCad's and SAMLight's "next line from a file", with its
// consumption committed by the serial store like a serial number (docs/store.md).
//
// The first row names the columns (non-empty, unique). Fields are separated by the delimiter
// (',' by default; ';' or a tab); a field may be quoted ("a, b"), a quote inside a quoted field
// is doubled (""); quoted fields may hold delimiters and line breaks. Lines end with LF or CRLF;
// empty lines are skipped; a UTF-8 byte order mark is dropped. Every malformed row is one error
// naming the file and line: "plates.csv:17: 3 fields, the header names 4 columns".
//
// A row's identity is its content (column names and values, identity()): the store never gives
// the same content to two parts, so a duplicated line, or a list edited and re-exported, cannot
// mark a row twice.
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mark {

struct DataRow {
  std::vector<std::string> values;  // one per column
  std::size_t line = 0;             // the line it starts on (1-based)
};

class DataList {
 public:
  DataList() = default;
  // `source` names the file in messages. Throws InputError("<source>:<line>: <problem>").
  static DataList parse(std::string_view text, const std::string& source, char delimiter = ',');
  // Reads and parses the file (at most kDataListMaxBytes). Throws InputError naming it.
  static DataList read(const std::string& path, char delimiter = ',');

  const std::string& source() const { return source_; }
  const std::vector<std::string>& columns() const { return columns_; }
  std::size_t size() const { return rows_.size(); }
  const DataRow& row(std::size_t i) const { return rows_.at(i); }
  std::optional<std::size_t> column(std::string_view name) const;
  // Row i as {column: value}, for rendering.
  std::map<std::string, std::string> values(std::size_t i) const;
  // Row i's content, unambiguously encoded with its column names (what the store hashes).
  std::string identity(std::size_t i) const;

 private:
  std::string source_;
  std::vector<std::string> columns_;
  std::vector<DataRow> rows_;
};

// ',' ';' or '\t' from the job file's "delimiter" ("," ";" "tab"); nothing otherwise.
std::optional<char> parse_delimiter(std::string_view name);

}  // namespace mark
