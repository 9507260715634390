// The null shift per micrometre of one side's bore (issue 61): a side built off the tables' bores
// takes the table's flows times the closed forms' ratio at its own bores (E21, E22) and the jet
// force plus E23's change (system/valve_equations.cc). At the reduced-order level that is exact; at
// the field level it applies the closed forms' derivative to the field's C_d. This driver measures
// that way's error where it matters, in the null shift per micrometre of the left orifice bore and
// of the left nozzle bore, against the pilot tables recomputed by the same level at that bore and
// used for the left side. Forward differences over `delta' for both ways (the same finite step:
// what is compared is the method, not the derivative). The valve is nulled at 40 degC; the null
// shift is read at 80 and 120 degC. The motor and spring tube are at the reduced-order level (they
// enter both ways alike). Steps of +-delta: where the tables' two one-sided differences disagree,
// the recomputed tables carry noise (each bore has its own mesh) as large as the effect.
//   build/bench/bench_bore_sensitivity [field|reduced-order] [delta, m] [output directory]
// Writes <output>/bore_sensitivity.csv; a field run takes five flow sweeps of 3 temperatures (about
// 25 min on 2 ranks); tables left in <output> by an earlier run of the same descriptions are reused.
#include "bench/benchmarks.h"
#include "common/output_files.h"
#include "common/stage_output.h"
#include "common/sweep.h"
#include "flow/pilot/pilot_stage.h"
#include "magnetics/torque_motor_stage.h"
#include "structure/spring_tube_stage.h"
#include "system/valve_model.h"

#include <deal.II/base/mpi.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

using namespace servodrift;
using namespace servodrift::system;

namespace
{
  std::string number(double x)
  {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
  }

  ValveDescription valve(const std::string &level, const std::string &directory, const std::vector<std::string> &more)
  {
    std::vector<std::string> settings = {"Output/Directory=" + directory, "Output/Progress=none", "Output/Plots=false",
                                         "Torque motor/Model level=reduced-order", "Spring tube/Model level=reduced-order",
                                         "Pilot stage/Model level=" + level, "Dynamics/Enabled=false",
                                         "Sweeps/Table temperatures=40, 80, 120", "Sweeps/Drift temperatures=40, 80, 120"};
    settings.insert(settings.end(), more.begin(), more.end());
    return load_valve_description("", settings);
  }

  /// The null-shift current at T of `offsets' nulled at T0, the left side's pilot stage read from
  /// `left_tables' when given [A].
  double null_shift(const ValveModel &m, const Offsets &offsets, double T, const StageFunctions *left_tables)
  {
    auto equations = [&](double t) {
      const ValveEquations e = m.equations(t, offsets);
      return left_tables ? e.with_side_tables(left, *left_tables) : e;
    };
    const double x_n = m.nulling_hydraulic_null(equations(m.description().operating.reference_temperature));
    return m.null_shift_current(equations(T).with_hydraulic_null(x_n)).value();
  }
} // namespace

int servodrift::bench::bench_bore_sensitivity(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string level = argc > 1 ? argv[1] : "field";
  const double delta = argc > 2 ? std::atof(argv[2]) : 2e-6;
  const std::string out = argc > 3 ? argv[3] : (std::filesystem::temp_directory_path() / "servodrift-bench-bores").string();

  const ValveDescription nominal = valve(level, out + "/nominal", {"Pilot stage/Bore sensitivity/Tables=on"});
  const double d0 = nominal.pilot.fixed_orifice_diameter, dN = nominal.pilot.nozzle_diameter;
  // the left side's tables at each bore: orifice +delta, -delta, nozzle +delta, -delta
  std::vector<ValveDescription> sides;
  for (const double step : {delta, -delta})
    sides.push_back(valve(level, out + "/orifice" + number(step), {"Pilot stage/Fixed orifice diameter=" + number(d0 + step)}));
  for (const double step : {delta, -delta})
    sides.push_back(valve(level, out + "/nozzle" + number(step), {"Pilot stage/Nozzle diameter=" + number(dN + step)}));
  for (const ValveDescription *v : std::vector<const ValveDescription *>{&nominal, &sides[0], &sides[1], &sides[2], &sides[3]})
    {
      // tables a previous run left in the same directory for the same description are reused
      const std::string tables = tables_directory(*v);
      bool reuse = std::filesystem::exists(tables + "/nozzle_flapper.csv") &&
                   (v->pilot.bore_sensitivity.tables != BoreSensitivityParameters::Tables::on ||
                    std::filesystem::exists(tables + "/nozzle_flapper_bore.csv"));
      if (reuse)
        {
          const StageTables t = StageTables::read(tables, *v);
          reuse = t.warnings.empty() || t.fixed_orifice.parameters_sha256 == v->parameters_sha256;
        }
      if (reuse)
        continue;
      magnetics::run(*v);
      structure::run(*v);
      flow::run(*v);
    }
  // the nominal tables with their bore tables, and without (the closed forms' ratio stands in)
  const StageTables with_bore_tables = StageTables::read(tables_directory(nominal), nominal);
  StageTables without = with_bore_tables;
  without.fixed_orifice_bore.reset();
  without.nozzle_flapper_bore.reset();
  const ValveModel model(nominal, with_bore_tables), closed_forms(nominal, without);
  const double rated = 0.02, per_um = 1e-6 / rated * 100;

  std::ostringstream csv;
  csv << "# null shift per micrometre of the left bore: by the bore tables (step `Pilot stage/Bore sensitivity/Tables "
         "step') and by the closed forms' ratio on the nominal tables, against the left side's tables recomputed at "
         "that bore (pilot stage: "
      << level << "; forward differences over +-" << delta << " m, and their central difference)\n"
      << "bore,temperature[degC],step[m],by_tables_at_the_bore[%rated/um],by_bore_tables[%rated/um],"
         "bore_tables_error[1],by_closed_forms[%rated/um],closed_forms_error[1]\n";
  for (const bool orifice : {true, false})
    for (const double T : {80.0, 120.0})
      {
        const double base = null_shift(model, {}, T, nullptr); // the same without bore tables
        double law[2], table[2], bore[2];
        for (int k = 0; k < 2; ++k)
          {
            const double step = k == 0 ? delta : -delta;
            const ValveDescription &v = sides[(orifice ? 0 : 2) + k];
            const StageFunctions left_tables(StageTables::read(tables_directory(v), v));
            Offsets built;
            (orifice ? built.sides[left].orifice_diameter : built.sides[left].nozzle_diameter) = step;
            law[k] = (null_shift(closed_forms, built, T, nullptr) - base) / step * per_um;
            bore[k] = (null_shift(model, built, T, nullptr) - base) / step * per_um;
            table[k] = (null_shift(model, {}, T, &left_tables) - base) / step * per_um;
          }
        const auto line = [&](const std::string &step, double reference, double by_bore, double by_law) {
          csv << (orifice ? "orifice" : "nozzle") << "," << T << "," << step << "," << reference << "," << by_bore << ","
              << std::abs(by_bore - reference) / std::abs(reference) << "," << by_law << ","
              << std::abs(by_law - reference) / std::abs(reference) << "\n";
        };
        for (int k = 0; k < 2; ++k)
          line(number(k == 0 ? delta : -delta), table[k], bore[k], law[k]);
        line("central", 0.5 * (table[0] + table[1]), 0.5 * (bore[0] + bore[1]), 0.5 * (law[0] + law[1]));
      }
  if (mpi_rank() == 0)
    {
      std::cout << csv.str();
      std::ofstream(out + "/bore_sensitivity.csv") << csv.str();
    }
  return 0;
}
