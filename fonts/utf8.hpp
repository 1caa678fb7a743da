#pragma once
// UTF-8 to code points, strict: an invalid sequence is an error naming its byte offset.
#include <string>
#include <string_view>
#include <vector>

namespace mark {

// Throws InputError("<what>: invalid UTF-8 at byte N").
std::u32string decode_utf8(std::string_view text, std::string_view what = "text");
std::string encode_utf8(char32_t code_point);

}  // namespace mark
