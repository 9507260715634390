#pragma once
// The valve description: every parameter of the valve, of the sweeps and of the output, declared
// through deal.II's ParameterHandler in one subsection per part (model.md section 2, decisions of
// section 0). Defaults are the built-in valve RV-1, so no input file is needed.
#include "common/parameters/armature.h"
#include "common/parameters/asymmetry.h"
#include "common/parameters/dynamics.h"
#include "common/parameters/fits.h"
#include "common/parameters/flow_solver.h"
#include "common/parameters/fluid.h"
#include "common/parameters/offsets.h"
#include "common/parameters/operating_conditions.h"
#include "common/parameters/output.h"
#include "common/parameters/pilot_stage.h"
#include "common/parameters/spool.h"
#include "common/parameters/spring_tube.h"
#include "common/parameters/sweeps.h"
#include "common/parameters/thermal_expansion.h"
#include "common/parameters/tolerances.h"
#include "common/parameters/torque_motor.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace dealii { class ParameterHandler; }

namespace servodrift
{
  struct ValveDescription
  {
    OperatingConditions operating;
    TorqueMotorParameters torque_motor;
    ThermalExpansion expansion;
    SpringTubeParameters spring_tube;
    ArmatureParameters armature;
    PilotStageParameters pilot;
    SpoolParameters spool;
    FluidParameters fluid;
    FlowSolverParameters flow_solver;
    OffsetParameters offsets;
    AsymmetryParameters asymmetry;
    SweepParameters sweeps;
    DynamicsParameters dynamics;
    ToleranceParameters tolerances;
    FitParameters fits;
    OutputParameters output;

    std::string source;            ///< the input file, or "built-in RV-1"
    std::string parameter_file;    ///< the complete, documented parameter file as used (PRM)
    std::string parameters_sha256; ///< sha256 of the values as used, without the Output and Tolerances subsections (they change no table)
  };

  enum class ParameterFormat
  {
    prm,      ///< deal.II PRM with documentation: the format of examples/rv1.prm
    json,     ///< deal.II JSON, readable again as input
    markdown, ///< the parameter reference of doc/parameters.md
  };

  /// Every subsection's values from `source' (the structs' parse_parameters, in declaration order).
  void parse_valve_description(ParameterSource &source, ValveDescription &valve);
  /// A complete parameter file as servodrift printed it (parameters.prm of an output directory or
  /// of an FMU's resources), read without deal.II: every entry must be present; the ranges are
  /// not checked again (deal.II checked them when it wrote the file). `parameters_sha256' stays
  /// empty. Throws InputError naming the file and the entry.
  ValveDescription read_printed_valve_description(const std::string &path);

  /// Defaults (RV-1), then the input file if any (.prm or .json), then each override
  /// "Subsection/Key=value" in order; then validate(). Throws InputError with a one-line message
  /// naming the file or override, the entry and the allowed range.
  ValveDescription load_valve_description(const std::string &input_file = "",
                                          const std::vector<std::string> &overrides = {});

  /// A numeric entry of the valve description: its value (in the declared unit) and declared range.
  struct NumericEntry
  {
    std::string path;   ///< "Subsection/Key"
    double value;       ///< as set by the input file and overrides
    double lower, upper; ///< the declared range
    std::string unit;   ///< the declared unit (the doc string's [...])
  };
  /// The entry `path' of the description made of `input_file' and `overrides'. Throws InputError
  /// naming the entry when it does not exist or is not a number (Double or Integer).
  NumericEntry numeric_entry(const std::string &input_file, const std::vector<std::string> &overrides,
                             const std::string &path);

  /// Many variants of one valve description that differ in a few entries (a calibration's trial
  /// values): the file and overrides are read once, each variant sets its entries and parses the
  /// values (no parameter text, no hash: about 50 times cheaper than load_valve_description).
  class ValveDescriptionVariants
  {
  public:
    ValveDescriptionVariants(const std::string &input_file, const std::vector<std::string> &overrides);
    ~ValveDescriptionVariants();
    /// The description with each "Subsection/Key" set to its value, validated. Throws InputError.
    ValveDescription with(const std::vector<std::pair<std::string, std::string>> &entries);

  private:
    std::unique_ptr<dealii::ParameterHandler> prm;
    std::string source;
  };

  /// The complete documented parameter file with the values of the input file and overrides.
  std::string print_parameters(const std::string &input_file, const std::vector<std::string> &overrides,
                               ParameterFormat format);

  /// Checks that go beyond one entry's range (p_r < p_s, d < D, x0 <= D_N/4, positive torque-motor
  /// gaps at every temperature, temperatures inside the oil law's window, ...): the structs' validate
  /// members (common/parameters/*_validation.cc) in a fixed order, and the functions below. Throws
  /// InputError for the first fault.
  void validate(const ValveDescription &valve);
  /// The checks of a whole run (`servodrift run'): the tables the stages will make must cover what
  /// the system model asks of them (the pilot tables the whole pressure span). A stage run alone
  /// may tabulate less. Throws InputError.
  void validate_table_ranges(const ValveDescription &valve);
  /// The checks of the dynamics' parameters (frequencies, amplitudes within the torque table, the
  /// table reaching the nozzle contacts); validate() runs them when `Dynamics/Enabled'.
  void validate_dynamics(const ValveDescription &valve);
  /// The asymmetric valve's left and right parts physical (validate() runs it).
  void validate_asymmetry(const ValveDescription &valve);
  /// The tolerance study's distributions, correlations and spec; validate() runs it when
  /// `Tolerances/Enabled'.
  void validate_tolerances(const ValveDescription &valve);
  /// The null-shift spec: > 0, and a table that is increasing, within 0-100 % and covers the drift
  /// temperatures (tolerance_validation.cc)
  void validate_null_shift_spec(const ValveDescription &valve);
} // namespace servodrift
