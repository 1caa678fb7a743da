// Data lists (CSV, RFC 4180): quoted fields with delimiters, doubled quotes and line breaks,
// CRLF, a byte order mark, empty lines, other delimiters; every malformed row refused in one
// line naming file and line; a row's identity is its content with its column names.
#include <gtest/gtest.h>

#include "base/error.hpp"
#include "marker/vars/data_list.hpp"

namespace mark {
namespace {

std::string refusal(std::string_view text, char delimiter = ',') {
  try {
    DataList::parse(text, "plates.csv", delimiter);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(DataList, ReadsQuotedFieldsAsRfc4180Says) {
  const DataList l = DataList::parse(
      "\xEF\xBB\xBFplate,owner,note\r\n"
      "A-1,\"Smith, J.\",plain\r\n"
      "\r\n"
      "A-2,\"say \"\"hi\"\"\",\"two\nlines\"\n"
      "A-3,,\"\"\n",
      "plates.csv");
  ASSERT_EQ(l.columns(), (std::vector<std::string>{"plate", "owner", "note"}));
  ASSERT_EQ(l.size(), 3u);
  EXPECT_EQ(l.row(0).values, (std::vector<std::string>{"A-1", "Smith, J.", "plain"}));
  EXPECT_EQ(l.row(0).line, 2u);
  EXPECT_EQ(l.row(1).values, (std::vector<std::string>{"A-2", "say \"hi\"", "two\nlines"}));
  EXPECT_EQ(l.row(1).line, 4u);
  EXPECT_EQ(l.row(2).values, (std::vector<std::string>{"A-3", "", ""}));
  EXPECT_EQ(l.row(2).line, 6u);  // the quoted line break counts
  EXPECT_EQ(l.values(1).at("owner"), "say \"hi\"");
  EXPECT_EQ(l.column("note"), 2u);
  EXPECT_FALSE(l.column("Note"));
}

TEST(DataList, OtherDelimiters) {
  const DataList l = DataList::parse("a;b\n1,5;2\n", "x.csv", ';');
  EXPECT_EQ(l.row(0).values, (std::vector<std::string>{"1,5", "2"}));
  EXPECT_EQ(DataList::parse("a\tb\n1\t2\n", "x.tsv", '\t').row(0).values, (std::vector<std::string>{"1", "2"}));
  EXPECT_EQ(parse_delimiter("tab"), '\t');
  EXPECT_FALSE(parse_delimiter("|"));
}

TEST(DataList, EveryMalformedRowNamesFileAndLine) {
  EXPECT_EQ(refusal("a,b\n1,2\n3\n"), "plates.csv:3: 1 field, the header names 2 columns");
  EXPECT_EQ(refusal("a,b\n1,2,3\n"), "plates.csv:2: 3 fields, the header names 2 columns");
  EXPECT_EQ(refusal("a,b\n1,\"open\n2,3\n"), "plates.csv:2: a quoted field opened on this line is never closed");
  EXPECT_EQ(refusal("a,b\n1,x\"y\n"),
            "plates.csv:2: a quote inside an unquoted field: quote the whole field (\"…\") and double the quotes "
            "inside it");
  EXPECT_EQ(refusal("a,b\n\"1\"x,2\n"),
            "plates.csv:2: text after the closing quote of a field (a field is either quoted whole or not at all)");
  EXPECT_EQ(refusal("a,b\r1,2\n"), "plates.csv:1: a carriage return that does not end the line (lines end with LF or CRLF)");
  EXPECT_EQ(refusal("a,,b\n"), "plates.csv:1: column 2 of the header has no name");
  EXPECT_EQ(refusal("a,a\n"), "plates.csv:1: two columns are called \"a\"");
  EXPECT_EQ(refusal(std::string("a\n1\0\n", 5)), "plates.csv:2: a NUL byte (a data list is text)");
  EXPECT_EQ(refusal("\n\n"), "plates.csv: empty: a data list starts with a header row naming its columns");
  EXPECT_EQ(refusal("a\n" + std::string(5000, 'x') + "\n"), "plates.csv:2: a field longer than 4096 bytes");
}

TEST(DataList, RowIdentityIsContentWithColumnNames) {
  const DataList l = DataList::parse("a,b\n1,2\n1,2\n12,\n", "x.csv");
  EXPECT_EQ(l.identity(0), l.identity(1));  // a duplicated line is the same row
  EXPECT_NE(l.identity(0), l.identity(2));  // "1","2" is not "12",""
  const DataList renamed = DataList::parse("a,c\n1,2\n", "y.csv");
  EXPECT_NE(l.identity(0), renamed.identity(0));
}

TEST(DataList, ReadRefusesAMissingFile) {
  try {
    DataList::read("/nonexistent/plates.csv");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/plates.csv: cannot read the data list: No such file or directory");
  }
}

}  // namespace
}  // namespace mark
