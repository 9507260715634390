#pragma once
// Sweeps: a sweep is a list of independent cases. Under `mpirun -np N' the cases are shared over
// the ranks of MPI_COMM_WORLD, handed out in case order to whichever rank is free (a one-sided
// counter on rank 0), the rows are gathered in case order on every rank, and only rank 0 writes
// files. Put the costly cases first: the last case to start sets the tail. Each case is computed
// by itself, so the result, and the table written from it, is byte-identical for any N.
#include "common/parameters/output.h"

#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace servodrift
{
  /// Progress of a sweep on stderr (rank 0 only): an updating line on a terminal, plain lines
  /// (at most one every two seconds) otherwise, and a closing line with the case count and time.
  class Progress
  {
  public:
    Progress(std::string label, std::size_t n_cases, OutputParameters::Progress mode);
    /// `done' cases finished, over all ranks (the estimate of the time left assumes the others
    /// take as long on average).
    void update(std::size_t done);
    void finish();

  private:
    std::string label;
    std::size_t n_cases;
    bool active, terminal;
    std::chrono::steady_clock::time_point start, last_print;
  };

  /// Call before MPI is initialised. A process that mpirun did not start is an Open MPI singleton:
  /// it has no peer, so unless the environment says otherwise it is asked
  /// - to run isolated (MCA `ess_singleton_isolated'): no daemon of its own (about 0.1 s), which
  ///   only spawning processes would need, and servodrift spawns none;
  /// - to leave out the cm point-to-point layer (MCA `pml ^cm'): its MTL components psm and psm2
  ///   load libinfinipath and libpsm2, whose constructors each sleep 0.1 s to calibrate a clock
  ///   (cornelisnetworks/opa-psm2#73), for an interconnect a singleton never uses. MPI_Init with
  ///   MPI_Finalize: 0.23 -> 0.03 s, in every test process and every command-line run.
  /// Other MPI implementations ignore the variables.
  void prepare_mpi_singleton();

  /// One thread per process: sweeps scale over MPI ranks, and OpenMP teams would only compete with
  /// them (CHOLMOD's supernodal factorisation asks for teams of a compiled-in 4 threads). Unless the
  /// environment sets OMP_THREAD_LIMIT, no OpenMP region is made active (max-active-levels 0), so
  /// every team has one thread. Setting OMP_THREAD_LIMIT here would come too late: libgomp reads it
  /// when it is loaded, before main. Call it first thing in main.
  void one_thread_per_process();

  using CaseRows = std::vector<std::vector<double>>;

  /// Runs cases 0..n_cases-1 over the MPI ranks and returns all rows, in case order, on every rank.
  /// An exception in any case is rethrown on every rank (the one of the lowest failing case) as a
  /// std::runtime_error with the same message, so that no rank waits for another.
  CaseRows run_sweep(const std::string &label, std::size_t n_cases,
                     const std::function<CaseRows(std::size_t case_index)> &compute_case,
                     OutputParameters::Progress progress);

  /// The bytes of rank `root' on every rank: a result one rank computed in a sweep that the others
  /// need afterwards (the fields a later sweep's cases start from). Without MPI, or on one rank,
  /// `bytes' itself.
  std::vector<char> broadcast_bytes(const std::vector<char> &bytes, unsigned int root);

  /// MPI rank and size of this process in MPI_COMM_WORLD (0 and 1 without MPI).
  unsigned int mpi_rank();
  unsigned int mpi_size();
} // namespace servodrift
