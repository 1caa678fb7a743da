#pragma once
// Line-by-line reading of a font file held in memory, without copying: the font parsers work on
// string_views into the file text and report 1-based line numbers in their errors.
#include <cstddef>
#include <string>
#include <string_view>

namespace mark::loaders {

class LineReader {
 public:
  // A UTF-8 byte-order mark at the start of the text is skipped (editors on Windows add one).
  explicit LineReader(std::string_view text) : text_(text) {
    if (text_.starts_with("\xEF\xBB\xBF")) pos_ = 3;
  }

  // The next line without its '\n' (and without a '\r' before it); false at the end of the text.
  bool next(std::string_view& line);
  // The line next() would return, without consuming it.
  bool peek(std::string_view& line) const;
  // Number of the line next() returned last (1-based); 0 before the first.
  std::size_t line_number() const { return line_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
};

// Without spaces and tabs at either end. Inline: the parsers call it for every number.
inline std::string_view trim(std::string_view s) {
  std::size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t')) ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t')) --e;
  return s.substr(b, e - b);
}
inline bool is_blank(std::string_view s) { return trim(s).empty(); }

// How the bytes of a text font file are to be read.
enum class TextEncoding { utf8, latin1 };

// Rejects binary data: control bytes other than tab, and (for UTF-8) invalid sequences. Throws
// FontFileError naming the line and the column.
void check_text_line(std::string_view line, TextEncoding encoding, const std::string& source,
                     std::size_t line_number);

// Calls f(field) for each part of `s` between separators (empty parts included).
template <class F>
void for_each_field(std::string_view s, char separator, F&& f) {
  while (true) {
    const std::size_t end = s.find(separator);
    if (end == std::string_view::npos) break;
    f(s.substr(0, end));
    s.remove_prefix(end + 1);
  }
  f(s);
}

// `text` quoted for a message, shortened to at most 40 bytes.
std::string quote(std::string_view text);

}  // namespace mark::loaders
