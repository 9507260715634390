#pragma once
#include <string>

namespace servodrift
{
  /// Lower-case hex sha256 of a byte string (OpenSSL's libcrypto).
  std::string sha256_hex(const std::string &data);
} // namespace servodrift
