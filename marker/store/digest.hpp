#pragma once
// SHA-256 of a job file for the audit log (OpenSSL's libcrypto).
#include <string>
#include <string_view>

namespace mark {

// Lower-case hex, 64 characters.
std::string sha256_hex(std::string_view bytes);

}  // namespace mark
