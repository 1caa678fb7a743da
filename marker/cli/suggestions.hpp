#pragma once
// "Did you mean": a mistyped option or command is refused in one line that names the closest
// one the command takes (`marker: mark: unknown option --hieght (did you mean --height?)`), as
// git and cargo do, instead of CLI11's "The following arguments were not expected".
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mark::cli {

// The known name closest to `typed` by edit distance (a swap of two neighbours counts one), when
// it is close enough to be a slip: at most 1 edit for names up to 4 characters, 2 up to 8, else 3;
// none for anything shorter than 4 characters ("-x" is one edit from every short option).
std::optional<std::string> closest_name(std::string_view typed, const std::vector<std::string>& known);

// The one line for a parse error of `app` (after app.parse threw `error`), with a suggestion
// where an unknown option or command has a close match; otherwise CLI11's own text.
std::string parse_error_line(const CLI::App& app, const CLI::ParseError& error);

}  // namespace mark::cli
