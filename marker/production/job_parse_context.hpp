#pragma once
// What object parsers need to know about the job being read.
#include <string>

namespace mark {

struct JobParseContext {
  std::string file;               // for messages
  double spot_diameter_um = 40;   // the job's spot: its radius is the default inset of fills
};

}  // namespace mark
