#pragma once
// What object parsers need to know about the job being read.
#include <string>

namespace mark {

struct JobParseContext {
  std::string file;  // for messages
};

}  // namespace mark
