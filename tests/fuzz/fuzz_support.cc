// fuzz_inputs' support: text helpers, file reading and writing, FNV-1a and shell quoting (Rng is in the header).
#include "fuzz_support.h"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace fuzz
{
  // ---- small text helpers -------------------------------------------------------------------------
  std::string shown(const std::string &s, std::size_t limit)
  {
    std::string out;
    for (std::size_t k = 0; k < s.size() && out.size() < limit; ++k)
      {
        const auto c = static_cast<unsigned char>(s[k]);
        if (c >= 0x20 && c < 0x7f)
          out += static_cast<char>(c);
        else
          {
            char hex[8];
            std::snprintf(hex, sizeof(hex), "\\x%02x", c);
            out += hex;
          }
      }
    if (out.size() >= limit && s.size() > limit)
      out += "... (" + std::to_string(s.size()) + " bytes)";
    return out;
  }

  std::string trim(const std::string &s)
  {
    const auto a = s.find_first_not_of(" \t\r");
    if (a == std::string::npos)
      return "";
    const auto b = s.find_last_not_of(" \t\r");
    return s.substr(a, b - a + 1);
  }

  std::string format_double(double x)
  {
    char buffer[40];
    std::snprintf(buffer, sizeof(buffer), "%.17g", x);
    return buffer;
  }

  std::string read_file(const fs::path &path)
  {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  void write_file(const fs::path &path, const std::string &content)
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << content;
  }

  std::uint64_t fnv1a(const std::string &bytes)
  {
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : bytes)
      h = (h ^ c) * 1099511628211ull;
    return h;
  }

  std::string sh_quote(const std::string &s)
  {
    std::string out = "'";
    for (char c : s)
      out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return out + "'";
  }
} // namespace fuzz
