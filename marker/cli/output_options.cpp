#include "marker/cli/output_options.hpp"

#include "base/error.hpp"
#include "marker/output/output_file.hpp"

namespace mark::cli {

void check_standard_output(std::initializer_list<std::pair<std::string_view, const std::string*>> outputs,
                           bool json) {
  std::string_view first;
  for (const auto& [option, path] : outputs) {
    if (!is_standard_output(*path)) continue;
    if (!first.empty())
      throw InputError(std::string(first) + " - and " + std::string(option) +
                       " - both write to standard output: give one of them a file name");
    first = option;
  }
  if (!first.empty() && json)
    throw InputError(std::string(first) + " - and --json both write to standard output: give " + std::string(first) +
                     " a file name, or leave out --json");
}

}  // namespace mark::cli
