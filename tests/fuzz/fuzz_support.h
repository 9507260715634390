#pragma once
// fuzz_inputs' support: seeded random numbers, small text helpers, file reading and writing, FNV-1a, shell quoting.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace fuzz
{
  namespace fs = std::filesystem;

  // ---- random numbers -----------------------------------------------------------------------------
  /// The standard distributions are implementation-defined; these helpers are not, so a seed means
  /// the same mutations with any standard library.
  struct Rng
  {
    std::mt19937_64 engine;

    Rng(std::uint64_t seed, std::uint64_t run)
    {
      std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                        static_cast<std::uint32_t>(run), static_cast<std::uint32_t>(run >> 32)};
      engine.seed(seq);
    }
    std::uint64_t below(std::uint64_t n) { return n == 0 ? 0 : engine() % n; }
    bool coin() { return engine() & 1; }
    template <typename T>
    const T &pick(const std::vector<T> &v) { return v[below(v.size())]; }
  };

  // ---- small text helpers -------------------------------------------------------------------------
  /// A string as a one-line description may show it: non-printable bytes as \xNN, at most `limit'
  /// characters, and the length when it was cut.
  std::string shown(const std::string &s, std::size_t limit = 48);

  std::string trim(const std::string &s);

  std::string format_double(double x);

  std::string read_file(const fs::path &path);

  void write_file(const fs::path &path, const std::string &content);

  /// FNV-1a (64 bit): enough to tell whether a file's bytes changed.
  std::uint64_t fnv1a(const std::string &bytes);

  /// An argument quoted for sh (any bytes but NUL survive single quotes).
  std::string sh_quote(const std::string &s);
} // namespace fuzz
