#include "common/provenance.h"

#include <openssl/evp.h>

#include <stdexcept>

namespace servodrift
{
  std::string sha256_hex(const std::string &data)
  {
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    if (EVP_Digest(data.data(), data.size(), digest, &length, EVP_sha256(), nullptr) != 1)
      throw std::runtime_error("sha256: OpenSSL EVP_Digest failed");
    static const char hex[] = "0123456789abcdef";
    std::string out;
    for (unsigned int k = 0; k < length; ++k)
      {
        out += hex[digest[k] >> 4];
        out += hex[digest[k] & 0xf];
      }
    return out;
  }
} // namespace servodrift
