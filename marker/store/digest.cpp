#include "marker/store/digest.hpp"

#include <openssl/evp.h>

#include <stdexcept>

namespace mark {

std::string sha256_hex(std::string_view bytes) {
  unsigned char md[EVP_MAX_MD_SIZE];
  unsigned int n = 0;
  if (EVP_Digest(bytes.data(), bytes.size(), md, &n, EVP_sha256(), nullptr) != 1 || n != 32)
    throw std::runtime_error("SHA-256 failed in libcrypto");
  static constexpr char kHex[] = "0123456789abcdef";
  std::string hex;
  hex.reserve(64);
  for (unsigned int i = 0; i < n; ++i) hex += kHex[md[i] >> 4], hex += kHex[md[i] & 15];
  return hex;
}

}  // namespace mark
