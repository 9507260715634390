#include "common/sweep.h"

#include "common/error.h"

#include <deal.II/base/mpi.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <omp.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>

namespace servodrift
{
  void prepare_mpi_singleton()
  {
    if (std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr) // started by mpirun: its settings stand
      return;
    ::setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
    ::setenv("OMPI_MCA_pml", "^cm", 0);
  }

  void one_thread_per_process()
  {
    if (std::getenv("OMP_THREAD_LIMIT") == nullptr) // a user's own limit stands
      omp_set_max_active_levels(0);
  }

  unsigned int mpi_rank()
  {
    return dealii::Utilities::MPI::job_supports_mpi() ? dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) : 0;
  }

  unsigned int mpi_size()
  {
    return dealii::Utilities::MPI::job_supports_mpi() ? dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) : 1;
  }

  std::vector<char> broadcast_bytes(const std::vector<char> &bytes, unsigned int root)
  {
    if (mpi_size() == 1)
      return bytes;
    return dealii::Utilities::MPI::broadcast(MPI_COMM_WORLD, bytes, root);
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

  void Progress::update(std::size_t done)
  {
    if (!active || n_cases == 0)
      return;
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start).count();
    const double since = std::chrono::duration<double>(now - last_print).count();
    if ((terminal && since < 0.1) || (!terminal && since < 2.0))
      return;
    last_print = now;
    const std::size_t k = std::min(n_cases, done);
    const double remaining = k > 0 ? elapsed * double(n_cases - k) / double(k) : 0.0;
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

  namespace
  {
    /// The cases of a sweep on more than one rank, handed out in order 0, 1, 2, ... to whichever
    /// rank asks next: a counter on rank 0 that each rank advances by MPI_Fetch_and_op (MPI-3
    /// passive-target one-sided communication; a window locked for the sweep's duration). A rank
    /// that finishes a cheap case takes the next one while another still works on a costly one, so
    /// a sweep whose cases differ in cost (the flow stage's chains: from seconds to minutes) ends
    /// when the work is done, not when the unluckiest fixed share is. The second counter counts the
    /// finished cases, for the progress line.
    class CaseDispenser
    {
    public:
      CaseDispenser()
      {
        MPI_Win_allocate(mpi_rank() == 0 ? 2 * sizeof(long long) : 0, sizeof(long long), MPI_INFO_NULL, MPI_COMM_WORLD,
                         &counters, &window);
        if (mpi_rank() == 0)
          {
            MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, window);
            counters[0] = counters[1] = 0;
            MPI_Win_unlock(0, window);
          }
        MPI_Barrier(MPI_COMM_WORLD); // the counters are set before any rank takes from them
        MPI_Win_lock_all(0, window);
      }
      ~CaseDispenser()
      {
        MPI_Win_unlock_all(window);
        MPI_Win_free(&window); // collective: every rank leaves the sweep through here
      }
      CaseDispenser(const CaseDispenser &) = delete;
      CaseDispenser &operator=(const CaseDispenser &) = delete;

      /// The next case to compute (>= n_cases: none left).
      std::size_t take() { return std::size_t(add(0, 1)); }
      /// No more cases for anyone (a case failed: the sweep fails, the others stop early).
      void close(std::size_t n_cases) { add(0, static_cast<long long>(n_cases)); }
      /// Counts a finished case; returns how many are finished, this one included.
      std::size_t finished() { return std::size_t(add(1, 1) + 1); }

    private:
      long long add(int counter, long long increment)
      {
        long long before = 0;
        MPI_Fetch_and_op(&increment, &before, MPI_LONG_LONG, 0, counter, MPI_SUM, window);
        MPI_Win_flush(0, window);
        return before;
      }
      long long *counters = nullptr;
      MPI_Win window = MPI_WIN_NULL;
    };
  } // namespace

  CaseRows run_sweep(const std::string &label, std::size_t n_cases,
                     const std::function<CaseRows(std::size_t)> &compute_case, OutputParameters::Progress mode)
  {
    const unsigned int size = mpi_size();
    Progress progress(label, n_cases, mode);

    // (case index, rows) for the cases of this rank; an error is (case index, message).
    std::vector<std::pair<std::size_t, CaseRows>> mine;
    std::vector<std::pair<std::size_t, std::string>> errors;
    {
      std::optional<CaseDispenser> dispenser;
      if (size > 1)
        dispenser.emplace();
      std::size_t next = 0; // one rank: the cases in turn
      auto next_case = [&] { return dispenser ? dispenser->take() : next++; };
      for (std::size_t k = next_case(); k < n_cases; k = next_case())
        {
          try
            {
              mine.emplace_back(k, compute_case(k));
            }
          catch (const std::exception &e)
            {
              errors.emplace_back(k, e.what());
              if (dispenser)
                dispenser->close(n_cases);
              break; // the sweep fails; no need to compute more
            }
          progress.update(dispenser ? dispenser->finished() : next);
        }
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

#include "common/sweep_objects.h"

namespace servodrift::detail
{
  std::vector<double> pack_bytes(const std::string &bytes)
  {
    // [byte count, the bytes in 8-byte words]; memcpy keeps every bit pattern
    std::vector<double> row(1 + (bytes.size() + 7) / 8, 0.0);
    row[0] = static_cast<double>(bytes.size());
    if (!bytes.empty())
      std::memcpy(row.data() + 1, bytes.data(), bytes.size());
    return row;
  }

  std::string unpack_bytes(const std::vector<double> &row)
  {
    const auto size = static_cast<std::size_t>(row.at(0));
    if ((size + 7) / 8 + 1 != row.size())
      throw std::logic_error("object_of: the row does not hold an archive");
    std::string bytes(size, '\0');
    if (size > 0)
      std::memcpy(bytes.data(), row.data() + 1, size);
    return bytes;
  }
} // namespace servodrift::detail
