#include "common/output_files.h"

#include "common/error.h"

#include <unistd.h>

#include <cerrno>
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

namespace servodrift
{
  namespace fs = std::filesystem;

  struct OutputTransaction::Journal
  {
    fs::path root, undo;
    std::set<fs::path> existing_directories; ///< under root (and root) before the run
    struct Entry
    {
      fs::path path, backup; ///< backup empty: the run created the file
    };
    std::vector<Entry> entries;
    std::set<fs::path> journalled;
    bool done = false;

    /// Called before a file is installed at `path': keeps the file it replaces.
    void before_install(const fs::path &given)
    {
      const fs::path path = given.lexically_normal();
      if (!journalled.insert(path).second)
        return; // the first version is kept already, or this run created it
      std::error_code ec;
      if (!fs::exists(path, ec))
        {
          entries.push_back({path, {}});
          return;
        }
      fs::create_directories(undo, ec);
      const fs::path backup = undo / std::to_string(entries.size());
      fs::create_hard_link(path, backup, ec);
      if (ec) // another file system, or no hard links: a copy
        fs::copy_file(path, backup, fs::copy_options::overwrite_existing, ec);
      if (ec)
        throw InputError(path.string() + ": cannot keep the previous version for an undo (" + ec.message() + ")");
      entries.push_back({path, backup});
    }
  };

  namespace
  {
    OutputTransaction::Journal *open_journal = nullptr;
  }

  OutputTransaction::OutputTransaction(const std::string &directory)
    : journal(std::make_unique<Journal>())
  {
    journal->root = directory;
    journal->undo = journal->root / (".servodrift-undo." + std::to_string(::getpid()));
    std::error_code ec;
    if (fs::is_directory(journal->root, ec))
      {
        journal->existing_directories.insert(journal->root);
        for (auto it = fs::recursive_directory_iterator(journal->root, ec); !ec && it != fs::recursive_directory_iterator();
             it.increment(ec))
          if (it->is_directory(ec))
            journal->existing_directories.insert(it->path());
      }
    open_journal = journal.get();
  }

  OutputTransaction::~OutputTransaction()
  {
    try
      {
        if (!journal->done)
          {
            roll_back();
            remove_created_directories();
          }
      }
    catch (...) // a destructor does not throw; what could not be undone stays
      {
      }
    if (open_journal == journal.get())
      open_journal = nullptr;
  }

  void OutputTransaction::commit()
  {
    std::error_code ec;
    fs::remove_all(journal->undo, ec);
    journal->done = true;
    open_journal = nullptr;
  }

  void OutputTransaction::roll_back()
  {
    std::error_code ec;
    for (auto e = journal->entries.rbegin(); e != journal->entries.rend(); ++e)
      if (e->backup.empty())
        fs::remove(e->path, ec);
      else
        fs::rename(e->backup, e->path, ec);
    fs::remove_all(journal->undo, ec);
    journal->entries.clear();
    journal->done = true;
    open_journal = nullptr;
  }

  void OutputTransaction::remove_created_directories()
  {
    std::error_code ec;
    std::vector<fs::path> created;
    if (!journal->existing_directories.count(journal->root))
      created.push_back(journal->root);
    if (fs::is_directory(journal->root, ec))
      for (auto it = fs::recursive_directory_iterator(journal->root, ec); !ec && it != fs::recursive_directory_iterator();
           it.increment(ec))
        if (it->is_directory(ec) && !journal->existing_directories.count(it->path()))
          created.push_back(it->path());
    std::sort(created.begin(), created.end(), [](const fs::path &a, const fs::path &b) {
      return std::distance(a.begin(), a.end()) > std::distance(b.begin(), b.end());
    });
    for (const auto &d : created)
      if (fs::is_empty(d, ec))
        fs::remove(d, ec); // deepest first; a directory with files of another process stays
  }

  void install_file(const std::string &temporary, const std::string &path)
  {
    try
      {
        if (open_journal)
          open_journal->before_install(path);
      }
    catch (...)
      {
        std::remove(temporary.c_str());
        throw;
      }
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
      {
        const std::string reason = std::strerror(errno);
        std::remove(temporary.c_str());
        throw InputError(path + ": cannot replace (" + reason + ")");
      }
  }

  void remove_output_file(const std::string &path)
  {
    std::error_code ec;
    if (!fs::exists(path, ec))
      return;
    if (open_journal)
      open_journal->before_install(path); // kept for an undo, like a file it replaces
    fs::remove(path, ec);
    if (ec)
      throw InputError(path + ": cannot remove (" + ec.message() + ")");
  }

  bool is_non_finite_token(const std::string &token)
  {
    std::string t;
    for (char c : token)
      t += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (!t.empty() && (t[0] == '-' || t[0] == '+'))
      t.erase(0, 1);
    return t == "nan" || t == "inf" || t == "infinity" || t.rfind("nan(", 0) == 0;
  }

  void check_finite_text(const std::string &path, const std::string &content)
  {
    const auto dot = path.rfind('.');
    const std::string extension = dot == std::string::npos ? "" : path.substr(dot);
    if (extension != ".csv" && extension != ".json" && extension != ".md")
      return;
    const auto is_token_character = [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '(' || c == ')' || c == '_';
    };
    int line = 1;
    for (std::size_t k = 0; k < content.size();)
      {
        if (!is_token_character(content[k]))
          {
            line += content[k++] == '\n';
            continue;
          }
        std::size_t end = k;
        while (end < content.size() && is_token_character(content[end]))
          ++end;
        const std::string token = content.substr(k, end - k);
        if (is_non_finite_token(token))
          throw std::runtime_error(path + ":" + std::to_string(line) + ": a result is not a finite number (`" + token +
                                   "'); nothing was written. This is a defect of servodrift: please report it "
                                   "with the parameter file");
        k = end;
      }
  }

  std::string temporary_beside(const std::string &path) { return path + ".tmp." + std::to_string(::getpid()); }

  void write_file_atomically(const std::string &path, const std::string &content)
  {
    check_finite_text(path, content);
    const std::string temporary = temporary_beside(path);
    {
      std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
      if (!out)
        throw InputError(path + ": cannot write (" + std::strerror(errno) + ")");
      out << content;
      out.flush();
      if (!out)
        {
          std::remove(temporary.c_str());
          throw InputError(path + ": writing failed (disk full?)");
        }
    }
    install_file(temporary, path);
  }

  void prepare_output_directory(const std::string &directory)
  {
    std::error_code ec;
    if (fs::exists(directory, ec) && !fs::is_directory(directory, ec))
      throw InputError("output directory `" + directory + "' exists but is not a directory (choose another with -o)");
    fs::create_directories(directory, ec);
    if (ec)
      throw InputError("output directory `" + directory + "' cannot be created: " + ec.message() +
                       " (choose another with -o)");
    const std::string probe = directory + "/.servodrift-write-test." + std::to_string(::getpid());
    {
      std::ofstream out(probe);
      if (!out)
        throw InputError("output directory `" + directory + "' is not writable (choose another with -o)");
    }
    std::remove(probe.c_str());
  }

  std::string read_file(const std::string &path)
  {
    std::ifstream in(path, std::ios::binary);
    if (!in)
      throw InputError(path + ": cannot open (does it exist and is it readable?)");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  std::string read_text_file(const std::string &file, const std::string &what, std::size_t max_bytes)
  {
    std::error_code ec;
    const auto status = fs::status(file, ec); // follows links; does not open (a FIFO would block)
    if (ec || !fs::exists(status))
      throw InputError(file + ": cannot open " + what + " (does it exist and is it readable?)");
    if (fs::is_directory(status))
      throw InputError(file + ": is a directory, not " + what);
    if (!fs::is_regular_file(status))
      throw InputError(file + ": is not a regular file (a device, pipe or socket), not " + what);
    if (fs::file_size(file, ec) > max_bytes)
      throw InputError(file + ": is larger than " + std::to_string(max_bytes >> 20) + " MiB, not " + what);
    std::ifstream in(file, std::ios::binary);
    if (!in)
      throw InputError(file + ": cannot open " + what + " (is it readable?)");
    std::ostringstream s;
    s << in.rdbuf();
    const std::string text = s.str();
    for (std::size_t k = 0; k < text.size(); ++k)
      {
        const auto c = static_cast<unsigned char>(text[k]);
        if (c == 0 || (c < 0x20 && c != '\n' && c != '\r' && c != '\t' && c != '\f'))
          throw InputError(file + ": is not a text file (byte " + std::to_string(k) + " is a control character), not " +
                           what);
      }
    return text;
  }

  std::string format_cell(double value)
  {
    char buffer[40];
    std::snprintf(buffer, sizeof(buffer), "%.12g", value == 0.0 ? 0.0 : value); // no "-0"
    return buffer;
  }
} // namespace servodrift
