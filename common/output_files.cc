#include "common/output_files.h"

#include "common/error.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace servodrift
{
  void write_file_atomically(const std::string &path, const std::string &content)
  {
    const std::string temporary = path + ".tmp." + std::to_string(::getpid());
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
    if (std::rename(temporary.c_str(), path.c_str()) != 0)
      {
        const std::string reason = std::strerror(errno);
        std::remove(temporary.c_str());
        throw InputError(path + ": cannot replace (" + reason + ")");
      }
  }

  void prepare_output_directory(const std::string &directory)
  {
    namespace fs = std::filesystem;
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

  std::string format_cell(double value)
  {
    char buffer[40];
    std::snprintf(buffer, sizeof(buffer), "%.12g", value == 0.0 ? 0.0 : value); // no "-0"
    return buffer;
  }
} // namespace servodrift
