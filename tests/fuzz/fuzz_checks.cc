// The checks of one run against the promises for bad input (see fuzz_inputs.cc's top comment).
#include "fuzz_checks.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <system_error>

namespace fuzz
{
  Snapshot snapshot(const fs::path &dir)
  {
    Snapshot s;
    std::error_code ec;
    s.exists = fs::exists(fs::symlink_status(dir, ec));
    if (!s.exists || !fs::is_directory(dir, ec))
      return s;
    for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
      {
        const std::string rel = fs::relative(it->path(), dir).string();
        if (it->is_symlink(ec))
          s.entries[rel] = "link:" + fs::read_symlink(it->path(), ec).string();
        else if (it->is_directory(ec))
          s.entries[rel] = "dir";
        else
          s.entries[rel] = "file:" + std::to_string(fnv1a(read_file(it->path())));
      }
    return s;
  }

  namespace
  {
    /// What changed between two snapshots, for a failure line (first few differences).
    std::string differences(const Snapshot &before, const Snapshot &after)
    {
      if (before.exists != after.exists)
        return before.exists ? "the output directory was removed" : "the output directory was created";
      std::vector<std::string> d;
      for (const auto &[path, what] : before.entries)
        {
          const auto it = after.entries.find(path);
          if (it == after.entries.end())
            d.push_back("removed " + path);
          else if (it->second != what)
            d.push_back("changed " + path);
        }
      for (const auto &[path, what] : after.entries)
        if (!before.entries.count(path))
          d.push_back("added " + path);
      std::string s;
      for (std::size_t k = 0; k < d.size() && k < 4; ++k)
        s += (k ? ", " : "") + d[k];
      if (d.size() > 4)
        s += ", ... (" + std::to_string(d.size()) + " differences)";
      return s;
    }

    /// Temporary files (`*.tmp.*'), undo journals (`.servodrift-undo.*') and write probes left in `dir'.
    std::vector<std::string> leftovers(const fs::path &dir)
    {
      std::vector<std::string> found;
      std::error_code ec;
      if (!fs::is_directory(dir, ec))
        return found;
      for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
        {
          const std::string name = it->path().filename().string();
          if (name.find(".tmp.") != std::string::npos || name.rfind(".servodrift-undo.", 0) == 0 ||
              name.rfind(".servodrift-write-test.", 0) == 0)
            found.push_back(fs::relative(it->path(), dir).string());
        }
      return found;
    }
  } // namespace

  std::string non_finite_token(const fs::path &dir)
  {
    std::error_code ec;
    if (!fs::is_directory(dir, ec))
      return "";
    const auto is_word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
      {
        const std::string ext = it->path().extension().string();
        if (!it->is_regular_file(ec) || (ext != ".csv" && ext != ".json" && ext != ".md"))
          continue;
        const std::string text = read_file(it->path());
        int line = 1;
        for (std::size_t k = 0; k < text.size();)
          {
            if (!is_word(text[k]))
              {
                line += text[k++] == '\n';
                continue;
              }
            std::size_t e = k;
            while (e < text.size() && is_word(text[e]))
              ++e;
            std::string token = text.substr(k, e - k);
            std::transform(token.begin(), token.end(), token.begin(), [](unsigned char ch) { return std::tolower(ch); });
            if (token == "nan" || token == "inf" || token == "infinity")
              {
                const std::size_t from = k > 0 && (text[k - 1] == '-' || text[k - 1] == '+') ? k - 1 : k;
                return fs::relative(it->path(), dir).string() + ":" + std::to_string(line) + ": `" +
                       text.substr(from, e - from) + "'";
              }
            k = e;
          }
      }
    return "";
  }

  namespace
  {
    /// stderr of a refusal: exactly one line, printable ASCII, at most 400 characters, with the prefix
    /// its exit code promises. Returns what is wrong, or "".
    std::string stderr_problem(const std::string &err, int exit_code)
    {
      if (err.empty())
        return "stderr is empty";
      if (err.back() != '\n' || std::count(err.begin(), err.end(), '\n') != 1)
        return "stderr is " + std::to_string(std::count(err.begin(), err.end(), '\n')) + " lines, not one: `" + shown(err, 160) + "'";
      const std::string line = err.substr(0, err.size() - 1);
      for (unsigned char ch : line)
        if (ch < 0x20 || ch >= 0x7f)
          return "stderr has a non-printable or non-ASCII byte: `" + shown(line, 160) + "'";
      if (line.size() > 400)
        return "stderr line has " + std::to_string(line.size()) + " characters (more than 400)";
      const bool error = line.rfind("servodrift: error:", 0) == 0, usage = line.rfind("servodrift: usage error:", 0) == 0;
      if (!error && !usage)
        return "stderr does not start with `servodrift: error:' or `servodrift: usage error:': `" + shown(line, 160) + "'";
      if (exit_code == 2 && !usage)
        return "exit code 2 with an error that is not a usage error";
      if (exit_code == 1 && usage)
        return "exit code 1 with a usage error (README: 2)";
      return "";
    }
  } // namespace

  std::vector<Failure> check(const Mutation &m, const Outcome &o, const Snapshot &before, const fs::path &out_dir)
  {
    std::vector<Failure> f;
    if (o.timed_out)
      return {{"timeout", "did not end within the timeout (killed after " + format_double(std::round(o.seconds)) + " s)"}};
    if (o.signal)
      return {{"signal", std::string("killed by signal ") + std::to_string(o.signal) + " (" + strsignal(o.signal) + ")"}};

    if (o.exit_code != 0 && o.exit_code != 1 && !(o.exit_code == 2 && m.usage_allowed))
      f.push_back({"exit-code", "exit code " + std::to_string(o.exit_code)});
    if (m.expect_success && o.exit_code != 0)
      f.push_back({"refused-valid-input", "valid input refused with exit code " + std::to_string(o.exit_code)});
    if (m.expect_refusal && o.exit_code == 0)
      f.push_back({"accepted-bad-input", "input the documentation says is refused ran with exit code 0"});
    if (m.uses_secret && (o.err.find(secret_tag) != std::string::npos || o.out.find(secret_tag) != std::string::npos))
      f.push_back({"secret-echoed", "the included file's secret appears in " +
                                      std::string(o.err.find(secret_tag) != std::string::npos ? "stderr" : "stdout")});
    if (o.exit_code != 0)
      {
        if (const std::string p = stderr_problem(o.err, o.exit_code); !p.empty())
          f.push_back({"stderr-format", p});
        const Snapshot after = snapshot(out_dir);
        if (after.exists != before.exists || after.entries != before.entries)
          f.push_back({"output-changed", "refused, but " + differences(before, after)});
      }
    else if (const std::string t = non_finite_token(out_dir); !t.empty())
      f.push_back({"non-finite-output", "non-finite number in " + t});
    if (const auto l = leftovers(out_dir); !l.empty())
      f.push_back({"leftover", "left behind in the output directory: " + l.front() +
                                 (l.size() > 1 ? " and " + std::to_string(l.size() - 1) + " more" : "")});
    return f;
  }
} // namespace fuzz
