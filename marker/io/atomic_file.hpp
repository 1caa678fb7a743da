#pragma once
// Output files that are never seen half-written: the text goes to `path.part` next to the target
// and is renamed over it only once it is complete. Errors name the file (InputError).
#include <string>

namespace mark {

void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace mark
