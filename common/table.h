#pragma once
// Coefficient tables: the only thing the stages and the system model share (architecture.md
// "Tables", model.md D13). CSV with a '#' header a person can read and a program can check:
//
//   # servodrift-table torque_motor
//   # schema 1
//   # producer servodrift 0.1.0 (git 1a2b3c4) magnetics/reduced-order
//   # parameters-sha256 <sha256 of the parameter values used, without the Output subsection>
//   # rows 2457
//   # columns temperature[degC] angle[rad] current[A] torque[N*m] torque_error[N*m] flag[1]
//   temperature[degC],angle[rad],current[A],torque[N*m],torque_error[N*m],flag[1]
//   40,-0.00872664625997,-0.03,...
//
// The first n_axes columns of a schema are the grid axes (a full tensor grid); the others are
// values. flag: 0 = computed within the model's validity, 1 = a law was clamped to its validity
// window (C6), 2 = the field solver did not converge (the reduced-order value stands in), 3 = an
// exact limit of the field level (dp = 0 or a closed gap: no flow), 4 = a field value beyond the
// range where the field level was verified (it stands, with a warning). The number of rows is stamped so that a truncated
// file is refused.
#include <string>
#include <vector>

namespace servodrift
{
  struct Column
  {
    std::string name; ///< e.g. "torque"
    std::string unit; ///< e.g. "N*m"
    std::string header() const { return name + "[" + unit + "]"; }
  };

  struct TableSchema
  {
    std::string name;
    int version;
    std::vector<Column> columns;
    unsigned int n_axes; ///< the first n_axes columns span the grid
  };

  namespace schemas
  {
    extern const TableSchema torque_motor;   ///< (T, theta, i) -> torque, torque_error, flag
    extern const TableSchema spring_tube;    ///< T -> stiffness K_a, flag
    extern const TableSchema fixed_orifice;  ///< (T, dp) -> Q, C_d, Re, flag
    extern const TableSchema nozzle_flapper; ///< (T, gap, dp) -> Q, C_d, Re, flapper force, flag
    /// (T, dp) -> bore step, Q(D_0 + step)/Q(D_0), flag: the orifice's flow at another bore, where
    /// the closed forms' ratio does not hold (the field level; system/valve_equations.cc)
    extern const TableSchema fixed_orifice_bore;
    /// (T, gap, dp) -> bore step, Q and flapper force at D_N + step over those at D_N, flag
    extern const TableSchema nozzle_flapper_bore;
    /// The schema of a table name; throws InputError for an unknown name.
    const TableSchema &by_name(const std::string &name);
  } // namespace schemas

  namespace flags
  {
    constexpr double computed = 0;      ///< within the model's validity
    constexpr double clamped = 1;       ///< a law was clamped to its validity window (C6)
    constexpr double not_converged = 2; ///< the field solver did not converge: the reduced-order value stands in
    constexpr double limit = 3;         ///< an exact limit, not a solution (no flow: dp = 0 or a closed gap)
    constexpr double beyond_verified = 4; ///< a field value outside the range where the field level was
                                          ///< verified: it differs from the reduced-order value by more
                                          ///< than the stage's stated factor (flow/pilot/pilot_field_stage.cc)
    constexpr double time_averaged = 5;   ///< no steady solution: the time average of a time-accurate run
                                          ///< (its spread in flow/<geometry>_time_averages.csv)
    constexpr double field_reference = 6; ///< creeping flow (Re < 1, a cold oil) where the field value
                                          ///< differs from the reduced-order one by more than the stage's
                                          ///< factor: the closed forms leave their range and the field
                                          ///< level, verified against the creeping limit, is the reference
  } // namespace flags

  class Table
  {
  public:
    explicit Table(const TableSchema &schema);

    const TableSchema &schema() const { return *table_schema; }
    const std::string &name() const { return table_schema->name; }

    std::string producer;          ///< "servodrift <version> (git <rev>) <stage>/<level>"
    std::string parameters_sha256; ///< of the valve description used
    /// `# note ...' lines of the header, after `# rows': what a reader should know of the numbers
    /// (e.g. the discretisation error of the mesh that made them)
    std::vector<std::string> notes;
    std::vector<std::vector<double>> rows;

    /// Index of a column by name ("torque"); throws std::logic_error for a name not in the schema.
    std::size_t column_index(const std::string &name) const;
    std::vector<double> column(const std::string &name) const;

    std::string to_csv() const;
    /// Writes atomically (temporary file + rename).
    void write(const std::string &path) const;
    /// Reads and checks a table written by any servodrift stage. Refuses (InputError naming file,
    /// line and column) another table name, an unknown schema, a missing column, a non-numeric or
    /// non-finite cell, a short row and a row count that does not match the header.
    static Table read(const std::string &path, const std::string &expected_name);

  private:
    const TableSchema *table_schema;
  };
} // namespace servodrift
