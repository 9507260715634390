#pragma once
// Reduced-order level of the pilot stage (model.md 1.8-1.10): fixed orifice (E17, E21), nozzle
// curtain (E18, E22) and flapper force (E23), at one temperature; or the paper's fits (D2).
#include "common/thermal_laws.h"
#include "common/valve_description.h"

namespace servodrift
{
  struct OrificeState
  {
    double flow_rate = 0;             ///< Q [m^3/s]
    double discharge_coefficient = 0; ///< C_d = Q/(A sqrt(2 dp/rho)) [1]
    double reynolds_number = 0;       ///< as in E17 (fixed orifice) or E18 (nozzle) [1]
    double flapper_force = 0;     ///< nozzle only: force of the jet on the flapper (E23) [N]
    bool clamped = false;         ///< a law was clamped to its validity window (C6)
  };

  /// E21 (Lichtarowicz, Duggins & Markland): 1/C_d = 1/C_du + 20 (1 + 2.25 l/d)/Re with
  /// C_du = 0.827 - 0.0085 l/d; Re on the ideal velocity (E17), l/d of the bore. 0 at Re = 0.
  double lichtarowicz_discharge_coefficient(double reynolds_number, double length_over_diameter);

  /// E18: the nozzle curtain's Reynolds number Re_n = D_h C_dn v_ideal / nu, on the slot's hydraulic
  /// diameter D_h = 2 pi D_N h/(pi D_N + h) [1]; v_ideal = sqrt(2 dp/rho) [m/s], nu [m^2/s].
  double nozzle_reynolds_number(double nozzle_diameter, double gap, double discharge_coefficient,
                                double ideal_velocity, double kinematic_viscosity);

  class PilotClosedForms
  {
  public:
    PilotClosedForms(const ValveDescription &valve, double temperature);

    /// Fixed orifice at pressure difference dp = p_upstream - p_downstream >= 0 [Pa].
    OrificeState fixed_orifice(double pressure_difference) const;
    /// Nozzle-flapper gap h >= 0 [m] at dp = p_c - p_r >= 0 [Pa].
    OrificeState nozzle(double gap, double pressure_difference) const;

    /// Creeping (Stokes) flow through the fixed orifice: Sampson's flow through a hole in a thin
    /// wall and the bore's Poiseuille flow in series, dp = mu Q (3 + 8 l/(pi r))/r^3 (Dagan,
    /// Weinbaum and Pfeffer 1982; numerical creeping flows through short pores lie within about 6 %
    /// of it); in E21's terms C_d = Re/(4 pi (3 + 16 l/(pi D))) with Re on the ideal velocity (E17).
    /// The limit of the orifice's flow for Re -> 0.
    OrificeState creeping_fixed_orifice(double pressure_difference) const;

    /// Creeping (Stokes) flow through the nozzle bore of length `bore_length' and the gap h at dp:
    /// the bore's Poiseuille resistance 8 mu l_b/(pi r_N^4) in series with the land's radial flow
    /// 6 mu ln(r_land/r_N)/(pi h^3) (lubrication), C_dn on the curtain as E22's. The end effects at
    /// the bore's entry and at the land's edges are left out: the limit of the real flow for Re -> 0
    /// and h/r_N -> 0, the reference of the field level at the cold end (issue 65). E22 has the
    /// land's term only.
    OrificeState creeping_nozzle(double gap, double pressure_difference, double bore_length) const;

    /// E23: force of a jet of flow Q from a bore at dp = p_c - p_r on the flapper: the bore pressure
    /// on the nozzle's projection plus the momentum of the jet turned radial (times the paper-table
    /// scale under that law) [N]
    double jet_force(double pressure_difference, double flow_rate) const;

    double density() const { return rho; }
    double kinematic_viscosity() const { return nu; }
    const laws::PilotStageGeometry &geometry() const { return g; }

  private:
    PilotReducedOrderParameters::OrificeLaw orifice_law;
    PilotReducedOrderParameters::NozzleLaw nozzle_law;
    PilotReducedOrderParameters::FlapperForceLaw force_law;
    double curtain_discharge_coefficient; ///< C_d,inf of E22 [1]
    laws::PilotStageGeometry g;
    double T, rho, nu, mu;
    double force_scale = 1;     ///< paper-table flapper force: K_f,paper(T)/K_f,E23(T)
    bool force_clamped = false;

    OrificeState momentum_nozzle(double gap, double dp) const;
    double momentum_force(double dp, double flow_rate) const; ///< E23 unscaled [N]
  };
} // namespace servodrift
