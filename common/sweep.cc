#include "common/sweep.h"

#include "common/error.h"

#include <deal.II/base/mpi.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <sstream>

namespace servodrift
{
  unsigned int mpi_rank()
  {
    return dealii::Utilities::MPI::job_supports_mpi() ? dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) : 0;
  }

  unsigned int mpi_size()
  {
    return dealii::Utilities::MPI::job_supports_mpi() ? dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) : 1;
  }

  namespace
  {
    std::string seconds(double s)
    {
      char buffer[32];
      std::snprintf(buffer, sizeof(buffer), s < 10 ? "%.2f s" : "%.0f s", s);
      return buffer;
    }
  } // namespace

  Progress::Progress(std::string label_, std::size_t n, OutputParameters::Progress mode)
    : label(std::move(label_))
    , n_cases(n)
    , active(mode != OutputParameters::Progress::none && mpi_rank() == 0)
    , terminal(mode == OutputParameters::Progress::automatic && ::isatty(STDERR_FILENO))
    , start(std::chrono::steady_clock::now())
    , last_print(start)
  {}

  void Progress::update(std::size_t done, std::size_t share)
  {
    if (!active || share == 0)
      return;
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start).count();
    const double since = std::chrono::duration<double>(now - last_print).count();
    if ((terminal && since < 0.1) || (!terminal && since < 2.0))
      return;
    last_print = now;
    const std::size_t k = std::min(n_cases, done * n_cases / share);
    const double remaining = done > 0 ? elapsed * (share - done) / done : 0.0;
    std::ostringstream line;
    line << "[" << label << "] case " << k << " of " << n_cases << ", elapsed " << seconds(elapsed)
         << ", remaining " << seconds(remaining);
    if (terminal)
      std::cerr << "\r\033[K" << line.str() << std::flush;
    else
      std::cerr << line.str() << std::endl;
  }

  void Progress::finish()
  {
    if (!active)
      return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (terminal)
      std::cerr << "\r\033[K";
    std::cerr << "[" << label << "] " << n_cases << " cases in " << seconds(elapsed) << " on " << mpi_size()
              << (mpi_size() == 1 ? " rank" : " ranks") << std::endl;
  }

  CaseRows run_sweep(const std::string &label, std::size_t n_cases,
                     const std::function<CaseRows(std::size_t)> &compute_case, OutputParameters::Progress mode)
  {
    const unsigned int rank = mpi_rank(), size = mpi_size();
    Progress progress(label, n_cases, mode);

    // (case index, rows) for the cases of this rank; an error is (case index, message).
    std::vector<std::pair<std::size_t, CaseRows>> mine;
    std::vector<std::pair<std::size_t, std::string>> errors;
    const std::size_t share = rank < n_cases ? (n_cases - rank + size - 1) / size : 0;
    std::size_t done = 0;
    for (std::size_t k = rank; k < n_cases; k += size)
      {
        try
          {
            mine.emplace_back(k, compute_case(k));
          }
        catch (const std::exception &e)
          {
            errors.emplace_back(k, e.what());
            break; // the sweep fails; no need to compute more
          }
        progress.update(++done, share);
      }

    std::vector<std::vector<std::pair<std::size_t, CaseRows>>> all_rows{mine};
    std::vector<std::vector<std::pair<std::size_t, std::string>>> all_errors{errors};
    if (size > 1)
      {
        all_rows = dealii::Utilities::MPI::all_gather(MPI_COMM_WORLD, mine);
        all_errors = dealii::Utilities::MPI::all_gather(MPI_COMM_WORLD, errors);
      }
    const std::pair<std::size_t, std::string> *first_error = nullptr;
    for (const auto &list : all_errors)
      for (const auto &e : list)
        if (!first_error || e.first < first_error->first)
          first_error = &e;
    if (first_error)
      throw std::runtime_error(first_error->second);

    std::vector<const CaseRows *> by_case(n_cases, nullptr);
    for (const auto &list : all_rows)
      for (const auto &[k, rows] : list)
        by_case[k] = &rows;
    CaseRows out;
    for (std::size_t k = 0; k < n_cases; ++k)
      out.insert(out.end(), by_case[k]->begin(), by_case[k]->end());
    progress.finish();
    return out;
  }
} // namespace servodrift
