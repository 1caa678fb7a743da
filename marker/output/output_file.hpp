#pragma once
// Every file a command writes (previews, dose images, G-code, plans, JSON) goes through here:
// its path is checked before any work starts — so a mistyped folder is reported before a part
// is marked, not after — and the file is written whole or not at all: into a temporary file in
// the same directory, flushed to disk, then renamed over the target. A failed write leaves the
// target as it was and no temporary file behind. Errors name the file and the system's reason.
//
// A symbolic link is written through: its target (followed to the end) is replaced and the link
// stays. A FIFO, a device node or a socket is refused — replacing /dev/null or a named pipe by a
// regular file is never what was meant, and as root it would destroy a device node. "-" is
// standard output: the bytes are written there as they are (no temporary, nothing to rename),
// and from the moment a command claims standard output for a file, whatever else it prints
// goes to standard error, so the file arrives unmixed.
#include <initializer_list>
#include <string>
#include <string_view>

namespace mark {

// "-": standard output.
inline constexpr std::string_view kStandardOutput = "-";
inline bool is_standard_output(std::string_view path) { return path == kStandardOutput; }

// Throws InputError "OPTION 'PATH': REASON" unless a file can be created at `path` (or at the
// target of the link `path` is): the directory exists and is writable (a file is created and
// removed there to prove it), the target is not a directory, a FIFO, a device or a socket, and
// the extension of `path` (compared without case) is one of `extensions` when any are given.
// "-" is always accepted: it claims standard output (claim_standard_output).
void check_output_path(std::string_view option, const std::string& path,
                       std::initializer_list<std::string_view> extensions = {});

// Writes `bytes` to `path` whole (temporary file + fsync + rename). Throws InputError
// "output file 'PATH': REASON" on failure, leaving `path` untouched.
void write_file_whole(const std::string& path, std::string_view bytes);

// The extension of `path` in lower case with its dot (".png"), or "" when it has none.
std::string lower_extension(const std::string& path);
// The format a file is written in: its extension, or for "-" the first of `extensions` (a
// preview to standard output is SVG, a plan CSV).
std::string output_format(const std::string& path, std::initializer_list<std::string_view> extensions);

// The file a write to `path` replaces: `path`, or the end of the chain of symbolic links it
// starts (a relative target is relative to its link's folder). Throws InputError for a loop.
std::string write_target(const std::string& path);

// Standard output becomes the file's: what the program prints to it from now on goes to
// standard error, and write_file_whole("-") writes to where standard output was. Idempotent.
void claim_standard_output();
// Puts standard output back where it was (the command line does this when a command ends).
void release_standard_output();

}  // namespace mark
