#pragma once
// Writing outputs so that nothing half-written is ever left behind.
#include <cstddef>
#include <memory>
#include <string>

namespace servodrift
{
  /// Writes `content' to `path' through a temporary file in the same directory and a rename:
  /// a reader sees the old file or the new one, never a half-written one. check_finite_text first.
  void write_file_atomically(const std::string &path, const std::string &content);

  /// True for a cell or token that spells a non-finite number ("nan", "-nan", "inf", "Infinity", ...).
  bool is_non_finite_token(const std::string &token);

  /// Refuses (std::runtime_error naming `path', line and token) a .csv, .json or .md text that holds
  /// a non-finite number: no result file carries one (issue 24). gnuplot's .dat files may (their
  /// missing-value marker); other files are not looked at.
  void check_finite_text(const std::string &path, const std::string &content);

  /// The temporary file beside `path' that a writer fills before install_file() renames it.
  std::string temporary_beside(const std::string &path);

  /// Renames a complete `temporary' file (written beside `path') to `path', through the run's
  /// OutputTransaction if one is open. Removes `temporary' and throws InputError on failure.
  void install_file(const std::string &temporary, const std::string &path);

  /// Removes an output a previous run left that this run does not make (a stale file would be
  /// read with the new ones), through the run's OutputTransaction if one is open: an undo puts it
  /// back.
  void remove_output_file(const std::string &path);

  /// The files one run writes, as one transaction (issue 24: a run that fails leaves the output
  /// directory as it was). While it is open, every file installed is journalled: a file it
  /// replaces is kept as a hard link (or a copy) in <directory>/.servodrift-undo.<pid>/. commit()
  /// keeps the new files and drops the old ones; a transaction destroyed without commit() puts the
  /// old files back, removes the new ones and the directories the run created. One per process
  /// (each MPI rank journals the files it writes); a process killed outright leaves its undo
  /// directory behind.
  class OutputTransaction
  {
  public:
    explicit OutputTransaction(const std::string &directory);
    ~OutputTransaction();
    OutputTransaction(const OutputTransaction &) = delete;
    OutputTransaction &operator=(const OutputTransaction &) = delete;

    void commit();
    /// Puts the directory back as it was (the destructor's work, callable before an MPI barrier).
    void roll_back();
    /// Removes the directories this run created that are empty now (after every rank rolled back).
    void remove_created_directories();

    struct Journal; ///< opaque: the files this run installed and the versions they replaced

  private:
    std::unique_ptr<Journal> journal;
    friend void install_file(const std::string &, const std::string &);
  };

  /// Creates `directory' (with parents) and checks that a file can be written in it. Throws
  /// InputError naming the directory otherwise. Writes nothing that stays behind.
  void prepare_output_directory(const std::string &directory);

  /// Reads a whole file; throws InputError naming the file if it cannot be read.
  std::string read_file(const std::string &path);

  /// Reads a whole input file that must be text: refused (InputError naming the file, never
  /// echoing its content) unless it is a readable regular file (not a directory, device, pipe or
  /// socket, which is looked at without opening it: a FIFO would block) of at most `max_bytes' bytes
  /// with no NUL or other control character but tab, CR, LF and FF. `what' says what it should be
  /// ("a parameter file").
  std::string read_text_file(const std::string &path, const std::string &what, std::size_t max_bytes);

  /// "%.12g": the number format of every table and CSV output (12 digits survive a round trip of
  /// any value we tabulate, and the same value always prints the same way).
  std::string format_cell(double value);
} // namespace servodrift
