#pragma once
// Files a command writes: checked before any work starts (so a job never marks a part and then
// fails on its preview), and written whole — to a temporary name in the same folder, renamed
// over the target at the end — or not at all.
#include <functional>
#include <string>
#include <string_view>

namespace mark::cli {

// Throws InputError ("--preview /no/such/x.png: cannot write there: No such file or directory")
// if `path` cannot be created or replaced. An empty path is not checked.
void check_output_file(const std::string& path, std::string_view option);

// Calls write(tmp) with a temporary path beside `path` (same extension), then renames it to `path`. If write
// throws, the temporary file is removed and the exception passes on; `path` is untouched.
void write_file_whole(const std::string& path, const std::function<void(const std::string&)>& write);

}  // namespace mark::cli
