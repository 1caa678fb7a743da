#pragma once
// Every option that names a file a command writes (-o, --preview, --dose-png, --trace) also
// takes "-", standard output (marker/output/output_file.hpp). Standard output holds one thing:
// one such file, or the command's --json, not two.
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>

namespace mark::cli {

// Throws InputError naming the options when more than one of `outputs` (option, path) is "-", or
// one is while `json` prints to standard output too.
void check_standard_output(std::initializer_list<std::pair<std::string_view, const std::string*>> outputs,
                           bool json);

}  // namespace mark::cli
