#pragma once
// The benchmark drivers, one function each (bench/bench_<name>.cc), run by one program,
// build/bench/servodrift_bench (bench/bench_main.cc): `servodrift_bench <name> [arguments]', or
// through the link build/bench/bench_<name> to it. One program links the libraries once instead of
// once per driver.
namespace servodrift::bench
{
  int bench_bore_sensitivity(int argc, char **argv);
  int bench_calibration(int argc, char **argv);
  int bench_cold_start(int argc, char **argv);
  int bench_drift_map(int argc, char **argv);
  int bench_dynamics(int argc, char **argv);
  int bench_flow(int argc, char **argv);
  int bench_magnetics(int argc, char **argv);
  int bench_mesh_convergence(int argc, char **argv);
  int bench_narrow_gap_paths(int argc, char **argv);
  int bench_newton(int argc, char **argv);
  int bench_nozzle_chain(int argc, char **argv);
  int bench_orifice_march(int argc, char **argv);
  int bench_orifice_reynolds(int argc, char **argv);
  int bench_pilot_field(int argc, char **argv);
  int bench_structure(int argc, char **argv);
  int bench_tolerances(int argc, char **argv);
} // namespace servodrift::bench
