#include "marker/vars/data_list.hpp"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>

#include "base/error.hpp"
#include "base/input_file.hpp"
#include "marker/limits/data_list_limits.hpp"

namespace mark {
namespace {

// One pass over the text, record by record; every problem names the line it is on.
class CsvParser {
 public:
  CsvParser(std::string_view text, const std::string& source, char delimiter)
      : s_(text), source_(source), delim_(delimiter) {
    if (s_.substr(0, 3) == "\xEF\xBB\xBF") s_.remove_prefix(3);
  }

  // The next record and the line it starts on; nothing at the end of the text. An empty line
  // is a record of one empty field.
  bool next(std::vector<std::string>& fields, std::size_t& first_line) {
    if (i_ >= s_.size()) return false;
    fields.clear();
    first_line = line_;
    std::string field;
    for (;;) {
      field.clear();
      const bool more = read_field(field);
      fields.push_back(field);
      if (fields.size() > static_cast<std::size_t>(kDataListColumnsRange.max))
        fail(first_line, "more than " + std::to_string(kDataListColumnsRange.max) + " fields");
      if (!more) return true;
    }
  }

  [[noreturn]] void fail(std::size_t line, const std::string& problem) const {
    throw InputError(source_ + ":" + std::to_string(line) + ": " + problem);
  }

 private:
  // Reads one field; true when a delimiter follows (another field of this record), false at
  // the end of the record or of the text.
  bool read_field(std::string& out) {
    if (i_ < s_.size() && s_[i_] == '"') return read_quoted(out);
    while (i_ < s_.size()) {
      const char c = s_[i_];
      if (c == delim_) {
        ++i_;
        return true;
      }
      if (c == '\n' || c == '\r') return end_of_line();
      if (c == '"')
        fail(line_, "a quote inside an unquoted field: quote the whole field (\"…\") and double "
                    "the quotes inside it");
      append(out, c);
      ++i_;
    }
    return false;
  }

  bool read_quoted(std::string& out) {
    const std::size_t opened = line_;
    ++i_;
    for (;;) {
      if (i_ >= s_.size())
        fail(opened, "a quoted field opened on this line is never closed");
      const char c = s_[i_];
      if (c == '"') {
        if (i_ + 1 < s_.size() && s_[i_ + 1] == '"') {
          append(out, '"');
          i_ += 2;
          continue;
        }
        ++i_;
        break;
      }
      if (c == '\n') ++line_;
      append(out, c);
      ++i_;
    }
    if (i_ >= s_.size()) return false;
    if (s_[i_] == delim_) {
      ++i_;
      return true;
    }
    if (s_[i_] == '\n' || s_[i_] == '\r') return end_of_line();
    fail(line_, "text after the closing quote of a field (a field is either quoted whole or not "
                "at all)");
  }

  // At '\n' or '\r': consumes LF or CRLF.
  bool end_of_line() {
    if (s_[i_] == '\r') {
      if (i_ + 1 >= s_.size() || s_[i_ + 1] != '\n')
        fail(line_, "a carriage return that does not end the line (lines end with LF or CRLF)");
      ++i_;
    }
    ++i_;
    ++line_;
    return false;
  }

  void append(std::string& out, char c) {
    if (c == '\0') fail(line_, "a NUL byte (a data list is text)");
    if (out.size() >= static_cast<std::size_t>(kDataFieldMaxBytes))
      fail(line_, "a field longer than " + std::to_string(kDataFieldMaxBytes) + " bytes");
    out += c;
  }

  std::string_view s_;
  const std::string& source_;
  char delim_;
  std::size_t i_ = 0;
  std::size_t line_ = 1;
};

bool blank(const std::vector<std::string>& fields) { return fields.size() == 1 && fields[0].empty(); }

}  // namespace

DataList DataList::parse(std::string_view text, const std::string& source, char delimiter) {
  if (text.size() > static_cast<std::size_t>(kDataListMaxBytes))
    throw InputError(source + ": a data list is at most " + std::to_string(kDataListMaxBytes >> 20) + " MiB");
  DataList list;
  list.source_ = source;
  CsvParser p(text, source, delimiter);
  std::vector<std::string> fields;
  std::size_t line = 0;
  bool header = false;
  while (p.next(fields, line)) {
    if (blank(fields)) continue;
    if (!header) {
      std::set<std::string> seen;
      for (std::size_t c = 0; c < fields.size(); ++c) {
        if (fields[c].empty()) p.fail(line, "column " + std::to_string(c + 1) + " of the header has no name");
        if (!seen.insert(fields[c]).second) p.fail(line, "two columns are called \"" + fields[c] + "\"");
      }
      list.columns_ = fields;
      header = true;
      continue;
    }
    if (fields.size() != list.columns_.size())
      p.fail(line, std::to_string(fields.size()) + " field" + (fields.size() == 1 ? "" : "s") +
                       ", the header names " + std::to_string(list.columns_.size()) + " column" +
                       (list.columns_.size() == 1 ? "" : "s"));
    if (list.rows_.size() >= static_cast<std::size_t>(kDataListRowsRange.max))
      p.fail(line, "more than " + std::to_string(kDataListRowsRange.max) + " rows");
    list.rows_.push_back({fields, line});
  }
  if (!header) throw InputError(source + ": empty: a data list starts with a header row naming its columns");
  return list;
}

DataList DataList::read(const std::string& path, char delimiter) {
  return parse(read_input_file(path, "data list", static_cast<std::size_t>(kDataListMaxBytes)), path, delimiter);
}

std::optional<std::size_t> DataList::column(std::string_view name) const {
  const auto it = std::find(columns_.begin(), columns_.end(), name);
  if (it == columns_.end()) return std::nullopt;
  return static_cast<std::size_t>(it - columns_.begin());
}

std::map<std::string, std::string> DataList::values(std::size_t i) const {
  std::map<std::string, std::string> m;
  const DataRow& r = rows_.at(i);
  for (std::size_t c = 0; c < columns_.size(); ++c) m[columns_[c]] = r.values[c];
  return m;
}

std::string DataList::identity(std::size_t i) const {
  // Length-prefixed, so no choice of values can make two different rows encode alike.
  std::string id = "marker-data-row/1";
  const DataRow& r = rows_.at(i);
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    for (const std::string* s : {&columns_[c], &r.values[c]})
      id.append("\n").append(std::to_string(s->size())).append(":").append(*s);
  }
  return id;
}

std::optional<char> parse_delimiter(std::string_view name) {
  if (name == ",") return ',';
  if (name == ";") return ';';
  if (name == "tab" || name == "\t") return '\t';
  return std::nullopt;
}

}  // namespace mark
