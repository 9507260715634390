#pragma once
// Writing outputs so that nothing half-written is ever left behind.
#include <string>

namespace servodrift
{
  /// Writes `content' to `path' through a temporary file in the same directory and a rename:
  /// a reader sees the old file or the new one, never a half-written one.
  void write_file_atomically(const std::string &path, const std::string &content);

  /// Creates `directory' (with parents) and checks that a file can be written in it. Throws
  /// InputError naming the directory otherwise. Writes nothing that stays behind.
  void prepare_output_directory(const std::string &directory);

  /// Reads a whole file; throws InputError naming the file if it cannot be read.
  std::string read_file(const std::string &path);

  /// "%.12g": the number format of every table and CSV output (12 digits survive a round trip of
  /// any value we tabulate, and the same value always prints the same way).
  std::string format_cell(double value);
} // namespace servodrift
