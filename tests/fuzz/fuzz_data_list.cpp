// Fuzz target for the data-list (CSV) parser: any input either parses into a list whose
// invariants hold (named, unique columns; every row as wide as the header, no field over the
// limit, rows starting on ascending lines; each row's identity decodes back to its own content
// — so two different rows never share one) or throws InputError naming the file and, for a
// row, its line. Anything else is a bug. The first byte picks the delimiter (';', a tab, else ',').
#include <cstdint>
#include <set>
#include <string>
#include <string_view>

#include "base/error.hpp"
#include "fuzz_check.hpp"
#include "marker/limits/data_list_limits.hpp"
#include "marker/vars/data_list.hpp"

using mark::fuzz::broken;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const char delimiter = data[0] == ';' || data[0] == '\t' ? static_cast<char>(data[0]) : ',';
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    const mark::DataList list = mark::DataList::parse(text, "fuzz.csv", delimiter);
    if (list.columns().empty()) broken("a list without columns");
    const std::set<std::string> names(list.columns().begin(), list.columns().end());
    if (names.size() != list.columns().size() || names.count("")) broken("an empty or repeated column name");
    std::size_t line = 1;
    std::set<std::string> identities;
    std::set<std::vector<std::string>> contents;
    for (std::size_t i = 0; i < list.size(); ++i) {
      const mark::DataRow& r = list.row(i);
      if (r.values.size() != list.columns().size()) broken("a row not as wide as the header");
      if (r.line <= line) broken("rows out of line order");
      line = r.line;
      for (const std::string& v : r.values)
        if (static_cast<std::int64_t>(v.size()) > mark::kDataFieldMaxBytes) broken("a field over the limit");
      if (list.values(i).size() != list.columns().size()) broken("values() lost a column");
      identities.insert(list.identity(i));
      contents.insert(r.values);
    }
    // Equal content, equal identity; different content, different identity.
    if (identities.size() != contents.size()) broken("a row identity shared by different rows");
  } catch (const mark::InputError& e) {
    if (std::string_view(e.what()).rfind("fuzz.csv", 0) != 0) broken("an error that does not name the file");
  }
  return 0;
}
