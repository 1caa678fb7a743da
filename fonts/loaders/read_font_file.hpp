#pragma once
// A font file's bytes, read whole after checking it is a regular file of at most 64 MiB (the
// largest real font we know, LibreCAD's amiri-regular.lff, is 7.4 MB). Throws InputError
// "cannot read font file 'PATH': why".
#include <string>

namespace mark::loaders {

std::string read_font_file(const std::string& path);

}  // namespace mark::loaders
