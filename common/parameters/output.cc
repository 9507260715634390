#include "common/parameters/output.h"

#include "common/parameters/parameter_helpers.h"

namespace servodrift
{
  using namespace parameters;

  void OutputParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Directory", "servodrift-out", Patterns::DirectoryName(),
                      "Output directory; tables/, system/ and report.md go below it (the command "
                      "line's -o overrides it). [-]");
    prm.declare_entry("Plots", "true", Patterns::Bool(), "Write gnuplot plots of the drift maps. [-]");
    prm.declare_entry("Plot formats", "png, svg", Patterns::MultipleSelection("png|svg"),
                      "Image formats of the plots. [-]");
    prm.declare_entry("Progress", "auto", Patterns::Selection("auto|lines|none"),
                      "Progress of long sweeps on stderr: auto (an updating line on a terminal, plain "
                      "lines otherwise), lines, or none. [-]");
    prm.declare_entry("Magnetics fields", "40 0 0, 40 0.1 0, 40 0 0.02, 120 0.1 0.02",
                      Patterns::Anything(),
                      "Torque-motor field-level cases written as VTU files (A_z, B, |B|, H, material, "
                      "current density) with a .pvd collection under magnetics/: a comma-separated list "
                      "of `temperature angle current' triples in degC, deg and A that are points of the "
                      "sweep, or `all', or `none'. [-]");
    prm.declare_entry("Flow fields", "reference", Patterns::Selection("reference|all|none"),
                      "Field-level flow cases written as VTU files (p, velocity, k, epsilon, mu_t, y+) with "
                      ".pvd collections under flow/: those at the table temperature nearest the reference "
                      "temperature (a few MB each), all, or none. [-]");
    prm.declare_entry("Formats", "csv", Patterns::MultipleSelection("csv|mat|modelica"),
                      "Formats of the coefficient tables and the drift map: csv (always written: the stages "
                      "read it); mat adds tables/servodrift_tables.mat (MATLAB MAT v5, a struct per table with "
                      "its axes and N-D arrays, for MATLAB/Simulink and scipy.io.loadmat); modelica adds "
                      "tables/servodrift_tables.txt (Modelica text tables for CombiTable1Ds/2Ds). [-]");
    prm.declare_entry("FMU", "false", Patterns::Bool(),
                      "Whether `servodrift run' also writes servodrift_valve.fmu, the valve of its tables as "
                      "an FMI 2.0 FMU (Model Exchange and Co-Simulation), as `servodrift export-fmu' does. [-]");
    prm.leave_subsection();
  }
} // namespace servodrift
