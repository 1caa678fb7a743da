#pragma once
// Every file a command writes (previews, dose images, G-code, plans, JSON) goes through here:
// its path is checked before any work starts — so a mistyped folder is reported before a part
// is marked, not after — and the file is written whole or not at all: into a temporary file in
// the same directory, flushed to disk, then renamed over the target. A failed write leaves the
// target as it was and no temporary file behind. Errors name the file and the system's reason.
#include <initializer_list>
#include <string>
#include <string_view>

namespace mark {

// Throws InputError "OPTION 'PATH': REASON" unless a file can be created at `path`: the directory
// exists and is writable (a file is created and removed there to prove it), `path` is not a
// directory, and its extension (compared without case) is one of `extensions` when any are given.
void check_output_path(std::string_view option, const std::string& path,
                       std::initializer_list<std::string_view> extensions = {});

// Writes `bytes` to `path` whole (temporary file + fsync + rename). Throws InputError
// "output file 'PATH': REASON" on failure, leaving `path` untouched.
void write_file_whole(const std::string& path, std::string_view bytes);

// The extension of `path` in lower case with its dot (".png"), or "" when it has none.
std::string lower_extension(const std::string& path);

}  // namespace mark
