#include "marker/codes/code_reader.hpp"

#include "base/error.hpp"

namespace mark {

const std::vector<const CodeReader*>& code_readers() {
  static const std::vector<const CodeReader*> all{&zxing_reader(), &dmtx_reader(), &zbar_reader()};
  return all;
}

const CodeReader& named_code_reader(std::string_view name, const std::string& option) {
  std::string names;
  for (const CodeReader* r : code_readers()) {
    if (r->name() == name) return *r;
    names += (names.empty() ? "" : ", ") + std::string(r->name());
  }
  throw InputError(option + " '" + std::string(name) + "' is not one of " + names);
}

}  // namespace mark
