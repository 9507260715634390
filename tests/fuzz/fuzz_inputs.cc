// fuzz_inputs: a small, seeded fuzz driver of servodrift's promises for bad input (README "Using it",
// issue 24). Each run writes one randomly mutated valve description (or command line), runs
// `servodrift run' on it in a child process with a timeout and checks what the product promises;
// the newer surfaces (issue 62) likewise: `servodrift tolerances' and `dynamics' with hostile entries,
// `calibrate' with hostile measured-data files and --free entries, each on a copy of the pre-filled
// output directory, whose tables they read:
//   - it ends by itself with exit code 0 or 1 (2 only for command-line usage errors): no signal, no hang;
//   - on a non-zero exit, stderr is exactly one printable-ASCII line of at most 400 characters starting
//     "servodrift: error:" or "servodrift: usage error:", and the output directory is as it was;
//   - on exit 0 no .csv, .json or .md result holds a non-finite number;
//   - never a leftover temporary file or undo directory, never an echo of an included file's secret;
//   - a valid valve file placed after the --set options runs (apps/servodrift.cc: --set takes one
//     value per occurrence "so that the valve file may follow the options"); valid measured data
//     calibrate; input the documentation says is refused (a NUL in a measured cell, a --free entry
//     outside its range, ...) is refused.
// Standard library and POSIX only, so that it builds without the product's dependencies and judges the
// binary from the outside. Every run draws from its own generator seeded by (seed, run index): run k of
// seed s is the same mutation whatever --runs or --seconds say, and a failure is saved as a directory
// with the input and a cmd.sh that replays it.
//
//   fuzz_inputs --servodrift PATH --work DIR [--seed N] [--runs N] [--seconds S] [--timeout S] [--kinds K,...]
//               [--verbose] [--dry-run]
// --kinds limits the mutation kinds (value, structure, json, command-line, tolerances, dynamics,
// calibrate; default all): run k of seed s is the same for the same --kinds. --verbose prints every
// run's mutation and outcome; --dry-run only lists the mutations (which kinds the first runs of a seed
// draw, for the ctest short mode).
#include "fuzz_checks.h"
#include "fuzz_measured.h"
#include "fuzz_mutations.h"
#include "fuzz_process.h"
#include "fuzz_support.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

using namespace fuzz;

namespace
{
  // ---- the driver -------------------------------------------------------------------------------------------
  struct Options
  {
    std::string servodrift, work;
    std::uint64_t seed = 1;
    long runs = 40;
    double seconds = 0; ///< 0: no time budget
    double timeout = 60;
    std::array<bool, n_categories> kinds{}; ///< the mutation kinds drawn
    bool verbose = false;                   ///< a line for every run, not only the failed ones
    bool dry_run = false;                   ///< list the runs' mutations, run none of them
  };

  [[noreturn]] void usage(const std::string &problem)
  {
    std::cerr << "fuzz_inputs: " << problem << "\nusage: fuzz_inputs --servodrift PATH --work DIR [--seed N] [--runs N] "
                                                "[--seconds S] [--timeout S] [--kinds K,...] [--verbose] [--dry-run]\n";
    std::exit(2);
  }

  Options parse_options(int argc, char **argv)
  {
    Options o;
    o.kinds.fill(true);
    for (int k = 1; k < argc; ++k)
      {
        const std::string a = argv[k];
        if (a == "--verbose" || a == "--dry-run")
          {
            (a == "--verbose" ? o.verbose : o.dry_run) = true;
            continue;
          }
        if (k + 1 >= argc)
          usage("option " + a + " needs a value");
        const std::string v = argv[++k];
        try
          {
            if (a == "--servodrift")
              o.servodrift = v;
            else if (a == "--work")
              o.work = v;
            else if (a == "--seed")
              o.seed = std::stoull(v);
            else if (a == "--runs")
              o.runs = std::stol(v);
            else if (a == "--seconds")
              o.seconds = std::stod(v);
            else if (a == "--timeout")
              o.timeout = std::stod(v);
            else if (a == "--kinds")
              {
                o.kinds.fill(false);
                std::istringstream list(v);
                for (std::string kind; std::getline(list, kind, ',');)
                  {
                    std::size_t n = 0;
                    while (n < n_categories && kind != category_names[n])
                      ++n;
                    if (n == n_categories)
                      usage("unknown mutation kind `" + kind + "' in --kinds");
                    o.kinds[n] = true;
                  }
                if (std::find(o.kinds.begin(), o.kinds.end(), true) == o.kinds.end())
                  usage("--kinds names no mutation kind");
              }
            else
              usage("unknown option " + a);
          }
        catch (const std::logic_error &)
          {
            usage("bad value `" + v + "' for " + a);
          }
      }
    if (o.servodrift.empty() || o.work.empty())
      usage("--servodrift and --work are required");
    return o;
  }

  [[noreturn]] void fatal(const std::string &what, const Outcome &o)
  {
    std::cerr << "fuzz_inputs: " << what << " (exit " << o.exit_code << ", signal " << o.signal
              << (o.timed_out ? ", timed out" : "") << "); stderr:\n"
              << o.err;
    std::exit(2);
  }

  /// Default files, the --set options every run uses (only those the product declares) and the
  /// pre-filled output directory: one successful run plus sentinel files.
  Context prepare(const Options &opt, const fs::path &work)
  {
    Context c;
    c.servodrift = opt.servodrift;
    Outcome o = run_process({c.servodrift, "params"}, work, opt.timeout);
    if (o.exit_code != 0)
      fatal("`servodrift params' failed", o);
    c.prm_text = o.out;
    c.prm = parse_prm(c.prm_text);
    o = run_process({c.servodrift, "params", "--format", "json"}, work, opt.timeout);
    if (o.exit_code != 0)
      fatal("`servodrift params --format json' failed", o);
    c.json_text = o.out;
    write_file(work / "params.prm", c.prm_text);
    write_file(work / "params.json", c.json_text);
    if (c.prm.entries.empty())
      fatal("`servodrift params' printed no `set' line", o);
    for (auto k : c.prm.entries)
      c.values.push_back(c.prm.lines[k].value);
    c.ranges = numeric_ranges(c.json_text);

    const std::vector<std::pair<std::string, std::string>> wanted{
      {"Torque motor/Model level", "reduced-order"}, {"Spring tube/Model level", "reduced-order"},
      {"Pilot stage/Model level", "reduced-order"},  {"Dynamics/Enabled", "false"},
      {"Output/Plots", "false"},                     {"Output/Progress", "none"}};
    for (const auto &[path, value] : wanted)
      if (c.prm.has(path))
        c.fixed_sets.push_back(path + "=" + value);
      else
        std::cout << "note: no entry `" << path << "' in `servodrift params': not set\n";

    std::vector<std::string> args{c.servodrift, "run", "-o", "prefill"};
    for (const auto &s : c.fixed_sets)
      args.insert(args.end(), {"--set", s});
    o = run_process(args, work, opt.timeout);
    if (o.exit_code != 0)
      fatal("the unmutated run (for the pre-filled output directory) failed", o);
    if (const std::string t = non_finite_token(work / "prefill"); !t.empty())
      {
        c.unmutated_run_failed = true;
        std::cout << "FAIL [non-finite-output] unmutated run (" << (work / "prefill").string()
                  << "): non-finite number in " << t << "\n";
      }
    write_file(work / "prefill" / "sentinel.txt", "a file of the user's: a refused run must leave it as it is\n");
    fs::create_directories(work / "prefill" / "notes");
    write_file(work / "prefill" / "notes" / "sentinel.csv", "x,y\n1,2\n");
    std::error_code ec;
    for (const auto &e : fs::directory_iterator(work / "prefill" / "tables", ec))
      if (e.is_regular_file())
        c.tables["tables/" + e.path().filename().string()] = read_file(e.path());
    if (opt.kinds[calibrate_category])
      if (const std::string problem = make_measured_data(c, work, opt.timeout, o); !problem.empty())
        fatal(problem, o);
    return c;
  }

  /// The replay script of a failed run, beside its input in the saved run directory.
  std::string replay_script(const Context &c, const Mutation &m, bool prefilled, const Outcome &o)
  {
    std::ostringstream s;
    s << "#!/bin/sh\n# " << category_names[m.category] << ": " << m.description << "\n";
    s << "# observed: " << (o.timed_out ? "timeout" : o.signal ? "signal " + std::to_string(o.signal) : "exit " + std::to_string(o.exit_code))
      << "; stderr in stderr.txt, stdout in stdout.txt\n";
    s << "cd \"$(dirname \"$0\")\" || exit 1\nrm -rf out\n";
    if (prefilled)
      s << "cp -a ../../prefill out  # the output directory was pre-filled\n";
    if (!m.out_files.empty())
      s << "cp -a out-files/. out/  # with broken tables\n";
    if (!m.fifo.empty())
      s << "[ -p " << sh_quote(m.fifo) << " ] || mkfifo " << sh_quote(m.fifo) << "\n";
    if (!m.directory.empty())
      s << "mkdir -p " << sh_quote(m.directory) << "\n";
    s << "exec " << sh_quote(c.servodrift);
    for (const auto &a : m.args)
      s << " " << sh_quote(a);
    s << "\n";
    return s.str();
  }

  struct Tally
  {
    long runs = 0;
    std::map<std::string, long> exits, failures, by_category;
    long failed_runs = 0;
    long noisy_runs = 0; ///< exit 0 with stderr lines not from servodrift (a library's log): noted, not failed
  };

  std::string exit_label(const Outcome &o)
  {
    if (o.timed_out)
      return "timeout";
    if (o.signal)
      return "signal " + std::to_string(o.signal);
    return "exit " + std::to_string(o.exit_code);
  }

  /// One run: write the mutation into a fresh directory, set up the output directory, run, check.
  /// A passing run's directory is removed; a failing one is kept under failures/.
  void one_run(const Options &opt, const Context &c, const fs::path &work, long index, Tally &tally)
  {
    Rng rng(opt.seed, static_cast<std::uint64_t>(index));
    const Mutation m = mutation(rng, c, opt.kinds);
    const fs::path dir = work / "runs" / ("run-" + std::to_string(index));
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const auto &[name, content] : m.files)
      write_file(dir / name, content);
    if (!m.fifo.empty() && mkfifo((dir / m.fifo).c_str(), 0644) != 0)
      std::perror("fuzz_inputs: mkfifo");
    if (!m.directory.empty())
      fs::create_directories(dir / m.directory);
    // half the runs: no output directory; the other half: a previous run's results and sentinels; the
    // surfaces always the latter (its tables)
    const bool prefilled = m.tables || index % 2 == 1;
    if (prefilled)
      fs::copy(work / "prefill", dir / "out", fs::copy_options::recursive | fs::copy_options::copy_symlinks);
    for (const auto &[name, content] : m.out_files) // broken tables: in out/, and beside it for cmd.sh
      for (const fs::path &to : {dir / "out" / name, dir / "out-files" / name})
        {
          fs::create_directories(to.parent_path());
          write_file(to, content);
        }
    const Snapshot before = snapshot(dir / "out");

    std::vector<std::string> argv{c.servodrift};
    argv.insert(argv.end(), m.args.begin(), m.args.end());
    const Outcome o = run_process(argv, dir, opt.timeout);
    const std::vector<Failure> failures = check(m, o, before, dir / "out");

    ++tally.runs;
    ++tally.exits[exit_label(o)];
    ++tally.by_category[category_names[m.category]];
    // on success stderr may hold warnings; a line that is not servodrift's own is a library talking
    // (Ceres, glog, Open MPI): no promise broken, but worth a note
    if (o.exit_code == 0)
      {
        std::istringstream lines(o.err);
        for (std::string line; std::getline(lines, line);)
          if (line.rfind("servodrift: ", 0) != 0)
            {
              ++tally.noisy_runs;
              std::cout << "note [stderr-noise] run " << index << " (" << category_names[m.category] << ": "
                        << shown(m.description, 120) << "): `" << shown(line, 160) << "'" << std::endl;
              break;
            }
      }
    if (opt.verbose)
      {
        char seconds[32];
        std::snprintf(seconds, sizeof(seconds), "%.1f s", o.seconds);
        std::cout << "run " << index << " (" << category_names[m.category] << ": " << shown(m.description, 300) << "): "
                  << exit_label(o) << ", " << seconds
                  << (o.exit_code > 0 ? ": " + shown(o.err.substr(0, o.err.find('\n')), 200) : std::string()) << std::endl;
      }
    if (failures.empty())
      {
        fs::remove_all(dir);
        return;
      }
    ++tally.failed_runs;
    const fs::path saved = work / "failures" / ("run-" + std::to_string(index));
    write_file(dir / "cmd.sh", replay_script(c, m, prefilled, o));
    fs::permissions(dir / "cmd.sh", fs::perms::owner_exec, fs::perm_options::add);
    std::string summary = std::string(category_names[m.category]) + ": " + m.description + "\n" + exit_label(o) + "\n";
    for (const auto &f : failures)
      summary += f.kind + ": " + f.detail + "\n";
    write_file(dir / "description.txt", summary);
    fs::create_directories(saved.parent_path());
    fs::remove_all(saved);
    fs::rename(dir, saved);
    for (const auto &f : failures)
      {
        ++tally.failures[f.kind];
        std::cout << "FAIL [" << f.kind << "] run " << index << " (" << category_names[m.category] << ": "
                  << m.description << "): " << f.detail << "; reproducer: " << (saved / "cmd.sh").string() << "\n";
      }
    if (o.exit_code != 0 && !o.err.empty())
      std::cout << "     stderr: " << shown(o.err.back() == '\n' ? o.err.substr(0, o.err.size() - 1) : o.err, 400) << "\n";
    std::cout << std::flush;
  }
} // namespace

int main(int argc, char **argv)
{
  Options opt = parse_options(argc, argv);
  std::error_code ec;
  opt.servodrift = fs::absolute(opt.servodrift).string(); // runs execute in their own directories
  if (access(opt.servodrift.c_str(), X_OK) != 0)
    usage("`" + opt.servodrift + "' is not an executable");
  const fs::path work = fs::absolute(opt.work);
  fs::create_directories(work);
  // only what this driver writes is cleared: a previous invocation's runs and findings
  for (const char *d : {"runs", "failures", "prefill", "measured-source"})
    fs::remove_all(work / d);

  const auto start = std::chrono::steady_clock::now();
  const Context c = prepare(opt, work);
  std::cout << "fuzz_inputs: seed " << opt.seed << ", up to " << opt.runs << " runs"
            << (opt.seconds > 0 ? ", " + format_double(opt.seconds) + " s" : std::string()) << ", timeout "
            << format_double(opt.timeout) << " s, work " << work.string() << std::endl;

  Tally tally;
  // the binary may be relinked while we run (a build beside us): say so, or findings of two builds mix
  auto built = fs::last_write_time(opt.servodrift, ec);
  for (long k = 0; k < opt.runs; ++k)
    {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (opt.seconds > 0 && elapsed >= opt.seconds)
        break;
      if (const auto now = fs::last_write_time(opt.servodrift, ec); now != built)
        {
          std::cout << "note: " << opt.servodrift << " was rebuilt before run " << k
                    << ": this run and the later ones test the new binary" << std::endl;
          built = now;
        }
      if (opt.dry_run)
        {
          Rng rng(opt.seed, static_cast<std::uint64_t>(k));
          const Mutation m = mutation(rng, c, opt.kinds);
          ++tally.by_category[category_names[m.category]];
          std::cout << "run " << k << " (" << category_names[m.category] << ": " << shown(m.description, 300) << ")\n";
          continue;
        }
      one_run(opt, c, work, k, tally);
    }
  fs::remove_all(work / "runs", ec);
  if (c.unmutated_run_failed)
    {
      ++tally.failed_runs;
      ++tally.failures["non-finite-output"];
    }

  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  char seconds[32];
  std::snprintf(seconds, sizeof(seconds), "%.1f", elapsed);
  std::cout << "\nsummary: " << tally.runs << " runs in " << seconds << " s (seed "
            << opt.seed << ")\n  mutations:";
  for (const auto &[k, n] : tally.by_category)
    std::cout << " " << k << " " << n;
  std::cout << "\n  outcomes:";
  for (const auto &[k, n] : tally.exits)
    std::cout << " " << k << ": " << n << ";";
  if (tally.noisy_runs)
    std::cout << "\n  runs that succeeded with stderr lines not from servodrift (noted, not failed): " << tally.noisy_runs;
  std::cout << "\n  failed runs: " << tally.failed_runs;
  for (const auto &[k, n] : tally.failures)
    std::cout << "\n    " << k << ": " << n;
  std::cout << (tally.failed_runs ? "\n  reproducers: " + (work / "failures").string() + "/run-*/cmd.sh" : std::string())
            << std::endl;
  return tally.failed_runs ? 1 : 0;
}
