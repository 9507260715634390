#pragma once
// Field level of the pilot stage (model.md 4.2, D11): the fixed orifice and the nozzle-flapper gap as
// axisymmetric cases of the finite-volume solver, on the parametric meshes meshes/fixed_orifice.geo
// and meshes/nozzle_flapper.geo with every dimension at the case's temperature. A case is solved
// for a sequence of pressure differences, each starting from the previous converged fields
// (continuation); a nozzle case can also start from a neighbouring gap's fields (same topology).
//
// Extraction (model.md 4.2): Q from the outlet flux; C_d = Q/(A sqrt(2 dp/rho)) with dp from the
// upstream stagnation pressure (the inlet's total pressure); Re as in E17 (orifice) and E18 (nozzle);
// flapper force = 2 pi int (p - p_r) r dr over the flapper face.
#include "common/valve_description.h"
#include "flow/simplec.h"

#include <memory>
#include <string>

namespace servodrift::flow
{
  struct PilotFieldResult
  {
    double pressure_difference = 0;   ///< upstream stagnation minus downstream static [Pa]
    double flow_rate = 0;             ///< Q through the outlet [m^3/s]
    double discharge_coefficient = 0; ///< [1]
    double reynolds_number = 0;       ///< E17 (orifice) or E18 (nozzle) [1]
    double flapper_force = 0;         ///< nozzle: int (p - p_r) dA over the flapper, towards it [N]
    double land_force = 0;            ///< nozzle: int (p - p_r) dA over the land, away from the flapper [N]
    double bore_pressure = 0;         ///< nozzle: mean pressure of the bore's exit section, minus p_r [Pa]
    double minimum_pressure = 0;      ///< lowest pressure, relative to the outlet's [Pa]
    unsigned int iterations = 0;
  };

  /// Dimensions and fluid of one case, for the tests: the valve's at temperature T unless overridden.
  struct PilotFieldCase
  {
    double temperature;        ///< [degC]
    FluidProperties fluid;     ///< rho, mu at the temperature
    double resolution;         ///< mesh resolution (multiplies every cell count)
  };

  class FixedOrificeField
  {
  public:
    FixedOrificeField(const ValveDescription &valve, const PilotFieldCase &c);
    ~FixedOrificeField();
    /// Inlet total pressure dp above the outlet's static pressure [Pa], > 0.
    PilotFieldResult solve(double pressure_difference);
    /// Starts the next solve from another case's fields (same mesh topology: another temperature,
    /// or a laminar solution under a turbulent case).
    void initialize_from(const FixedOrificeField &other);
    /// Where a case that fails writes its last fields (VTU); empty: nowhere.
    void set_failure_output(const std::string &filename);
    void write_vtu(const std::string &filename) const;
    std::size_t n_cells() const;
    double bore_radius() const; ///< r_0(T) [m]
    const SimplecSolver &solver() const;
    const FvMesh &mesh() const;

  private:
    struct Implementation;
    std::unique_ptr<Implementation> impl;
  };

  class NozzleFlapperField
  {
  public:
    NozzleFlapperField(const ValveDescription &valve, const PilotFieldCase &c, double gap);
    ~NozzleFlapperField();
    PilotFieldResult solve(double pressure_difference);
    /// Starts the next solve from another gap's fields (same mesh topology).
    void initialize_from(const NozzleFlapperField &other);
    /// Where a case that fails writes its last fields (VTU); empty: nowhere.
    void set_failure_output(const std::string &filename);
    void write_vtu(const std::string &filename) const;
    std::size_t n_cells() const;
    const SimplecSolver &solver() const;
    const FvMesh &mesh() const;

  private:
    struct Implementation;
    std::unique_ptr<Implementation> impl;
  };

  /// The case at temperature T from the valve description: the oil's rho(T), mu(T), the field resolution.
  PilotFieldCase pilot_field_case(const ValveDescription &valve, double T);
} // namespace servodrift::flow
