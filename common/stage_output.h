#pragma once
// Where and how the stages write their results: <output>/tables/<name>.csv, stamped with producer
// and parameter hash, written by MPI rank 0 only, atomically; tables/fits.json with the fits of
// every table present.
#include "common/fitting.h"
#include "common/table.h"
#include "common/valve_description.h"

#include <functional>
#include <string>
#include <vector>

namespace servodrift
{
  std::string tables_directory(const ValveDescription &valve);
  std::string table_path(const ValveDescription &valve, const std::string &table_name);

  /// Stamps the table (producer "<stage>/<level>", parameter hash), writes it on rank 0 and waits
  /// until every rank can read it.
  void write_table(const ValveDescription &valve, Table &table, const std::string &stage_and_level,
                   const std::string &variant = "");

  /// Writes parameters.prm (as used) into the output directory (rank 0).
  void write_parameters_file(const ValveDescription &valve);

  /// The paper's forms and the general polynomials of one table (E25 for torque_motor, E26 for
  /// fixed_orifice, E27 for nozzle_flapper).
  std::vector<PolynomialFit> fits_of_table(const Table &table, const ValveDescription &valve);

  /// Fits every table present in <output>/tables, adds `extra' (e.g. E28 from the system model)
  /// and writes tables/fits.json (rank 0). Returns all fits.
  std::vector<PolynomialFit> write_fits(const ValveDescription &valve, const std::vector<PolynomialFit> &extra = {});

  /// Waits for all MPI ranks (no-op without MPI).
  void mpi_barrier();

  /// Runs `write' on rank 0 only (file output), then shares its outcome: if it threw, every rank
  /// throws the same message, so that no rank waits for one that has stopped.
  void on_rank_zero(const std::function<void()> &write);
} // namespace servodrift
