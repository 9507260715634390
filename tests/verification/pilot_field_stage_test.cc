// The pilot stage's field sweep (flow/pilot/pilot_field_stage): unconverged cases become flagged rows, and
// the fixed orifice's continuation path over temperature keeps the answer of a start from rest.
#include "common/csv.h"
#include "common/error.h"
#include "common/table.h"
#include "common/pilot_closed_forms.h"
#include "flow/pilot/pilot_field.h"
#include "flow/pilot/pilot_field_cases.h"
#include "flow/pilot/pilot_field_stage.h"
#include "tests/support/checks.h"
#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace servodrift::flow
{
  // A case that does not converge within the iteration limit becomes a flagged row (flag 2) that
  // carries the reduced-order value, never a silent number; no-flow rows are exact limits (flag 3).
  // Each such case is named in a note of its table (and so in the report), with its nearest steady
  // state's largest scaled residual, which flow/<geometry>_cases.csv lists too, and the VTU of that
  // state; a stall's residual lies above the solver's tolerance (else it would have converged).
  TEST(PilotFieldStage, UnconvergedCasesAreFlaggedRows)
  {
    ValveDescription v = test::valve({"Sweeps/Table temperatures=40, 120", "Sweeps/Drift temperatures=40, 120",
                                      "Sweeps/Field orifice pressure fractions=0.5", "Sweeps/Field gap fractions=1",
                                      "Sweeps/Field nozzle pressure fractions=0.5", "Flow solver/Maximum iterations=20",
                                      "Output/Flow fields=all"});
    const auto [orifice, nozzle] = compute_pilot_field_tables(v);
    const PilotClosedForms closed_forms(v, 40);
    ASSERT_EQ(orifice.rows.size(), 4u); // per temperature: dp = 0 and the case
    EXPECT_EQ(orifice.rows[0].back(), flags::limit);
    EXPECT_EQ(orifice.rows[1].back(), flags::not_converged);
    const double dp = orifice.rows[1][1];
    EXPECT_DOUBLE_EQ(orifice.rows[1][3], closed_forms.fixed_orifice(dp).discharge_coefficient);
    std::size_t flagged = 0;
    for (const auto &row : nozzle.rows)
      {
        EXPECT_TRUE(row.back() == flags::limit || row.back() == flags::not_converged);
        for (double x : row)
          EXPECT_TRUE(std::isfinite(x));
        flagged += row.back() == flags::not_converged;
      }
    EXPECT_EQ(flagged, 2u);

    for (const auto &[table, name] : {std::pair{&orifice, "fixed_orifice"}, std::pair{&nozzle, "nozzle_flapper"}})
      {
        const std::string directory = v.output.directory + "/flow/";
        std::ifstream file(directory + name + "_cases.csv");
        std::ostringstream text;
        text << file.rdbuf();
        const CsvDocument cases = CsvDocument::parse(text.str());
        std::size_t noted = 0;
        for (const auto &row : cases.rows)
          {
            if (row.at(cases.column("flag[1]")) != "2")
              continue;
            const double residual = std::stod(row.at(cases.column("largest_residual[1]")));
            const std::string equation = row.at(cases.column("largest_residual_equation[-]"));
            EXPECT_GT(residual, v.flow_solver.tolerance) << name;
            EXPECT_TRUE(std::isfinite(residual)) << name;
            const double T = std::stod(row.at(cases.column("temperature[degC]")));
            // the note: where, the residual as the CSV has it (both formatted from one number), the VTU
            const auto note = std::find_if(table->notes.begin(), table->notes.end(), [&](const std::string &n) {
              return n.rfind("flag 2 at " + format_number(T) + " degC", 0) == 0;
            });
            ASSERT_NE(note, table->notes.end()) << name << " at " << T << " degC: no note";
            EXPECT_NE(note->find(format_number(residual) + " (" + equation + ")"), std::string::npos) << *note;
            const std::size_t vtu = note->find("flow/");
            ASSERT_NE(vtu, std::string::npos) << *note;
            EXPECT_TRUE(std::ifstream(v.output.directory + "/" + note->substr(vtu))) << *note;
            ++noted;
          }
        EXPECT_EQ(noted, 2u) << name;
      }
  }

  // The nozzle table's note states the discretisation error that bench/bench_mesh_convergence wrote
  // to doc/benchmarks/nozzle_mesh_errors.csv (compiled in), not a figure typed into the code: its
  // range at the valve's resolution is the file's, to the note's 0.1 %; a resolution the bench did
  // not run, or another flow model, is said to be unmeasured.
  TEST(PilotFieldStage, NozzleTableStatesTheMeasuredMeshError)
  {
    std::ifstream file(SERVODRIFT_SOURCE_DIR "/doc/benchmarks/nozzle_mesh_errors.csv");
    ASSERT_TRUE(file) << "doc/benchmarks/nozzle_mesh_errors.csv";
    std::ostringstream text;
    text << file.rdbuf();
    const CsvDocument errors = CsvDocument::parse(text.str());
    double lowest = 1, highest = -1;
    for (const auto &row : errors.rows)
      if (std::stod(row.at(errors.column("resolution[1]"))) == 1)
        {
          const double error = std::stod(row.at(errors.column("discharge_coefficient_error[1]")));
          lowest = std::min(lowest, error), highest = std::max(highest, error);
        }
    ASSERT_LE(lowest, highest) << "no row at resolution 1";
    char range[64];
    std::snprintf(range, sizeof range, "C_dn %+.1f %% to %+.1f %%", 100 * lowest, 100 * highest);
    const std::string note = nozzle_mesh_error_note(test::valve({"Pilot stage/Model level=field"}));
    EXPECT_NE(note.find(range), std::string::npos) << note << "\nexpected " << range;
    EXPECT_NE(nozzle_mesh_error_note(test::valve({"Pilot stage/Field mesh/Resolution=1.7"})).find("not measured"),
              std::string::npos);
    EXPECT_NE(nozzle_mesh_error_note(test::valve({"Pilot stage/Field solution/Nozzle flow model=laminar"}))
                .find("for this flow model"),
              std::string::npos);
  }

  // The stage's fixed orifice is one continuation path over temperature (pilot_field_stage.h): the
  // colder temperature's first case starts from the hotter one's converged fields instead of from
  // rest. Only the path changes: at 80 degC (k-epsilon, 1.03 MPa) C_d must be that of a case started
  // from rest, within 3e-4 relative (each solve stops once its flow rate changes by less than 1e-4
  // over 50 iterations, so two converged solves from different starts could differ by a few 1e-5;
  // measured 2e-9), and the step from 90 degC must take less than half the iterations of the start
  // from rest (measured 621 against 2 852).
  SLOW_TEST(PilotFieldStage, OrificePathOverTemperatureKeepsTheAnswer)
  {
    ValveDescription v = test::valve({"Sweeps/Table temperatures=40, 80, 90", "Sweeps/Drift temperatures=40, 80, 90",
                                      "Sweeps/Field orifice pressure fractions=0.05", "Sweeps/Field gap fractions=1",
                                      "Sweeps/Field nozzle pressure fractions=0.15", "Output/Flow fields=none"});
    const auto [orifice, nozzle] = compute_pilot_field_tables(v);
    ASSERT_EQ(orifice.rows.size(), 6u); // per temperature: dp = 0 and the case
    const auto &row = orifice.rows[3];
    ASSERT_EQ(row[0], 80);
    ASSERT_EQ(row.back(), flags::computed);

    PilotFieldCase c = pilot_field_case(v, 80);
    c.turbulence = FlowSolverParameters::Turbulence::k_epsilon; // Re_0 above 1 000: the stage's choice too
    PilotField from_rest(pilot_field_settings(v), PilotGeometry::fixed_orifice, c);
    const PilotFieldResult r = from_rest.solve(row[1]);

    // the iterations of the stage's 80 degC case (flow/fixed_orifice_cases.csv)
    std::ifstream summary(v.output.directory + "/flow/fixed_orifice_cases.csv");
    std::string line;
    std::vector<std::string> header;
    unsigned int path_iterations = 0;
    while (std::getline(summary, line))
      {
        if (line.empty() || line[0] == '#')
          continue;
        std::vector<std::string> cells;
        std::stringstream split(line);
        for (std::string cell; std::getline(split, cell, ',');)
          cells.push_back(cell);
        if (header.empty())
          header = cells;
        else if (std::stod(cells[0]) == 80)
          for (std::size_t k = 0; k < header.size(); ++k)
            if (header[k] == "iterations[1]")
              path_iterations = unsigned(std::stoul(cells[k]));
      }
    std::printf("fixed orifice 80 degC, 1.03 MPa: C_d %.8f from 90 degC in %u iterations, %.8f from rest in %u\n",
                row[3], path_iterations, r.discharge_coefficient, r.iterations);
    EXPECT_CHECK_RELATIVE("orifice C_d at 80 degC, 1.03 MPa, k-epsilon, on the path from 90 degC", row[3],
                          r.discharge_coefficient, 3e-4, "from rest");
    ASSERT_GT(path_iterations, 0u);
    EXPECT_CHECK_AT_MOST("iterations on the path from 90 degC / from rest", double(path_iterations) / r.iterations, 0.5,
                         "fewer than half");
  }
} // namespace servodrift::flow
