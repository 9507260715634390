#pragma once
// Field level of the pilot stage (model.md 4.2, D11): the fixed orifice and the nozzle-flapper gap as
// axisymmetric cases of the finite-volume solver, on the parametric meshes meshes/fixed_orifice.geo
// and meshes/nozzle_flapper.geo with every dimension at the case's temperature.
//
// A case is solved at one pressure difference after another, each from the last converged fields
// scaled to the new pressure level (continuation), through intermediate levels where the step is
// larger than `Field solution/Continuation ratio' (the quasi-static path: laminar cavitating cases have more
// than one steady solution); a case can also start from another case's fields of the same mesh
// topology (another gap or temperature, or a laminar solution under a turbulent case). A case that
// starts from rest is first solved laminar at a pressure difference low enough for a steady laminar
// flow (ideal-velocity Reynolds number 300), then carried to its own.
//
// Extraction (model.md 4.2): Q from the outlet flux; C_d = Q/(A sqrt(2 dp/rho)) with dp from the
// upstream stagnation pressure (the inlet's total pressure); Re as in E17 (orifice) and E18 (nozzle);
// flapper force = 2 pi int (p - p_r) r dr over the flapper face; and for C12 the land's force, the
// axial momentum through the bore's exit and the lowest absolute pressure against the vapour pressure.
#include "common/parameters/pilot_field.h"
#include "common/thermal_laws.h"
#include "flow/fv/simplec.h"

#include <memory>
#include <string>

namespace servodrift::flow
{
  /// The nozzle case's bore, from its chamber to its exit, in bore radii: a modelling choice of the
  /// field level (meshes/nozzle_flapper.geo's lb). Its viscous resistance matters only in creeping
  /// flow at large gaps (a cold oil), where the flow depends on the real nozzle's bore length.
  constexpr double nozzle_bore_length_in_radii = 4;

  enum class PilotGeometry
  {
    fixed_orifice, ///< meshes/fixed_orifice.geo
    nozzle_flapper ///< meshes/nozzle_flapper.geo
  };

  struct PilotFieldResult
  {
    double pressure_difference = 0;   ///< upstream stagnation minus downstream static [Pa]
    /// Q [m^3/s] through the outlet (solve) or the inlet (advance: a time step's outlet flow carries
    /// the rate the vapour's volume changes at; flow/pilot/pilot_field_extraction.h)
    double flow_rate = 0;
    double discharge_coefficient = 0; ///< [1]
    double reynolds_number = 0;       ///< E17 (orifice) or E18 (nozzle) [1]
    double flapper_force = 0;         ///< nozzle: int (p - p_r) dA over the flapper, towards it [N]
    double land_force = 0;            ///< nozzle: int (p - p_r) dA over the land, away from the flapper [N]
    /// nozzle: axial momentum through the bore's exit plane, int (p - p_r + rho u_x^2) dA [N]; C12 (1)
    /// equates it with flapper_force - land_force
    double jet_force = 0;
    double bore_pressure = 0;             ///< nozzle: mean pressure of the bore's exit section, minus p_r [Pa]
    double minimum_pressure = 0;          ///< lowest pressure, relative to the outlet's [Pa]
    double minimum_absolute_pressure = 0; ///< the same, absolute (the downstream gauge pressure + ambient) [Pa]
    /// with cavitation: some cell cavitates; without: the lowest absolute pressure is below the vapour pressure (C12)
    bool cavitating = false;
    double max_wall_y_plus = 0;           ///< largest y+ of a wall-adjacent cell centre [1]
    double max_turbulent_viscosity_ratio = 0; ///< largest mu_t/mu of a cell (0 if laminar) [1]
    unsigned int iterations = 0;          ///< SIMPLEC iterations of this solve (start-up included)
    unsigned int coarse_mesh_iterations = 0; ///< grid sequencing: iterations on the coarser meshes first
    /// time stepping (advance): the step met its tolerance within its iterations
    bool step_converged = true;
    /// the last iteration's scaled residuals: solve, at the case's level (below the tolerance);
    /// advance, the step's
    Residuals residuals;
    double pressure_relaxation = 0; ///< the pressure relaxation the solve ended with (lowered by caught cycles) [1]
    FlowSolverParameters::Turbulence turbulence = FlowSolverParameters::Turbulence::laminar;
  };

  /// What the pilot cases read of the valve description, not the whole of it: the field level's
  /// mesh and solution settings, the flow solver's, and the pressures that set a case's outlet
  /// state and its cavitation.
  struct PilotFieldSettings
  {
    PilotFieldMeshParameters mesh;
    PilotFieldSolutionParameters solution;
    FlowSolverParameters solver;
    double supply_pressure;  ///< p_s, gauge [Pa]
    double return_pressure;  ///< p_r, gauge [Pa]
    double ambient_pressure; ///< added to a gauge pressure for the absolute one [Pa]
    double vapour_pressure;  ///< absolute [Pa]
  };

  /// The pilot cases' slice of the valve description
  PilotFieldSettings pilot_field_settings(const ValveDescription &valve);

  /// Fluid, resolution, flow model and dimensions of one case: the valve's at temperature T unless
  /// overridden.
  struct PilotFieldCase
  {
    double temperature;    ///< [degC]
    FluidProperties fluid; ///< rho, mu at the temperature
    double resolution;     ///< mesh resolution (multiplies every cell count)
    FlowSolverParameters::Turbulence turbulence; ///< the flow model of this case
    laws::PilotStageGeometry dimensions; ///< the pilot stage's dimensions at the temperature (2.3)
  };

  /// The case at temperature T from the valve description: the oil's rho(T), mu(T), the field
  /// resolution, the valve's flow solver model (the stage chooses per case, pilot_field_sweep) and
  /// the dimensions at T.
  PilotFieldCase pilot_field_case(const ValveDescription &valve, double T);

  class PilotField
  {
  public:
    /// The fixed orifice (gap ignored) or the nozzle-flapper case at `gap' > 0 [m].
    PilotField(const PilotFieldSettings &settings, PilotGeometry geometry, const PilotFieldCase &c, double gap = 0);
    ~PilotField();
    PilotField(PilotField &&) noexcept;

    /// Inlet total pressure dp above the outlet's static pressure [Pa], > 0 (InputError otherwise).
    /// Throws NotConverged (fields left as they are) or std::runtime_error (diverged).
    PilotFieldResult solve(double pressure_difference);
    /// Time stepping (SimplecSolver::advance): one step of dt [s] at pressure difference dp
    /// from the current fields (scaled to dp first if they are at another level), at most
    /// max_iterations to `tolerance'; what the new fields give, iterations those of the step.
    PilotFieldResult advance(double pressure_difference, double dt, unsigned int max_iterations, double tolerance);
    /// The time step of Courant number `courant' for the current fields [s].
    double courant_time_step(double courant) const;
    /// Starts the next solve from another case's fields (same mesh topology: another temperature
    /// or gap, or another flow model).
    void initialize_from(const PilotField &other);
    FlowFields fields() const;
    void set_fields(const FlowFields &fields);
    bool at_rest() const; ///< nothing solved or given yet: the next solve starts up laminar
    /// The largest ratio of successive pressure levels on the path of the next solves (default:
    /// `Pilot stage/Field solution/Continuation ratio'), > 1.
    void set_continuation_ratio(double ratio);

    /// Where a case that fails writes its last fields (VTU); empty: nowhere.
    void set_failure_output(const std::string &filename);
    void write_vtu(const std::string &filename) const;
    std::size_t n_cells() const;
    PilotGeometry geometry() const;
    double gap() const;              ///< nozzle-flapper gap h [m]
    double bore_radius() const;      ///< r_0(T) (orifice) or D_N(T)/2 (nozzle) [m]
    /// Ideal-velocity Reynolds number of a pressure difference: 2 r_0 sqrt(2 dp/rho)/nu (orifice,
    /// E17) or 2 h sqrt(2 dp/rho)/nu (nozzle: E18 with C_dn = 1 and D_h = 2h).
    double ideal_reynolds_number(double pressure_difference) const;
    const SimplecSolver &solver() const;
    SimplecSolver &solver(); ///< the case's solver itself (another steady solver on its fields)
    const FvMesh &mesh() const;

  private:
    struct Implementation;
    std::unique_ptr<Implementation> impl;
  };
} // namespace servodrift::flow
