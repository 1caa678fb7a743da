#include "marker/cli/commands.hpp"

namespace mark::cli {

std::vector<Command> all_commands() {
  std::vector<Command> c;
  return c;
}

}  // namespace mark::cli
