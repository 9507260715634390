#include "common/pilot_closed_forms.h"

#include "common/pilot_bridge.h"
#include "common/units.h"
#include "common/paper_fits.h"

#include <cmath>

namespace servodrift
{
  using units::pi;

  PilotClosedForms::PilotClosedForms(const ValveDescription &valve, double temperature)
    : orifice_law(valve.pilot.reduced_order.fixed_orifice_law)
    , nozzle_law(valve.pilot.reduced_order.nozzle_law)
    , force_law(valve.pilot.reduced_order.flapper_force_law)
    , curtain_discharge_coefficient(valve.pilot.reduced_order.nozzle_discharge_coefficient)
    , g(laws::pilot_stage_geometry(valve.pilot, valve.armature, valve.expansion, temperature,
                                   valve.operating.reference_temperature))
    , T(temperature)
  {
    const laws::Oil oil(valve.fluid, valve.operating.reference_temperature);
    rho = oil.density(T).value;
    nu = oil.kinematic_viscosity(T).value;
    mu = rho * nu;

    if (force_law == PilotReducedOrderParameters::FlapperForceLaw::paper_table)
      {
        // Scale E23 so that the blocked-bridge flow-force stiffness at null equals the paper's K_f(T):
        // K_f,E23 by central differences of the bridge with the momentum force (1.10, 4.2).
        const double p_s = valve.operating.supply_pressure, p_r = valve.operating.return_pressure;
        const double dx = 1e-3 * g.null_gap;
        auto force = [&](double gap) {
          const double p = bridge_pressure(
            [&](double p_c) { return fixed_orifice(p_s - p_c).flow_rate - momentum_nozzle(gap, p_c - p_r).flow_rate; },
            p_s, p_r);
          return momentum_nozzle(gap, p - p_r).flapper_force;
        };
        // F_L - F_R = F(x0 - x_f) - F(x0 + x_f): its slope at x_f = 0 is -2 F'(x0)
        const double K_f_momentum = (force(g.null_gap - dx) - force(g.null_gap + dx)) / dx;
        const auto K_f_paper = paper::flow_force_stiffness(T);
        force_scale = K_f_paper.value / K_f_momentum;
        force_clamped = K_f_paper.clamped;
      }
  }

  double lichtarowicz_discharge_coefficient(double reynolds_number, double length_over_diameter)
  {
    // E21
    const double C_du = 0.827 - 0.0085 * length_over_diameter;
    return reynolds_number > 0 ? 1.0 / (1.0 / C_du + 20.0 * (1.0 + 2.25 * length_over_diameter) / reynolds_number) : 0.0;
  }

  double nozzle_reynolds_number(double nozzle_diameter, double gap, double discharge_coefficient,
                                double ideal_velocity, double kinematic_viscosity)
  {
    // E18
    const double D_h = 2 * pi * nozzle_diameter * gap / (pi * nozzle_diameter + gap);
    return D_h * discharge_coefficient * ideal_velocity / kinematic_viscosity;
  }

  OrificeState PilotClosedForms::fixed_orifice(double dp) const
  {
    OrificeState s;
    const double D0 = g.fixed_orifice_diameter, A0 = 0.25 * pi * D0 * D0;
    const double ideal_velocity = std::sqrt(2 * dp / rho);
    s.reynolds_number = D0 * ideal_velocity / nu; // E17: on the ideal velocity
    if (orifice_law == PilotReducedOrderParameters::OrificeLaw::lichtarowicz)
      {
        s.discharge_coefficient = lichtarowicz_discharge_coefficient(s.reynolds_number, g.fixed_orifice_length / D0);
      }
    else
      {
        const auto c = paper::fixed_orifice_discharge_coefficient(s.reynolds_number); // E26, C6
        s.discharge_coefficient = c.value;
        s.clamped = c.clamped;
      }
    s.flow_rate = s.discharge_coefficient * A0 * ideal_velocity; // E31
    return s;
  }

  OrificeState PilotClosedForms::momentum_nozzle(double h, double dp) const
  {
    OrificeState s;
    const double DN = g.nozzle_diameter;
    const double curtain = pi * DN * h; // curtain area of the gap
    const double ideal_velocity = std::sqrt(2 * dp / rho);
    if (nozzle_law == PilotReducedOrderParameters::NozzleLaw::curtain)
      {
        if (h > 0 && dp > 0)
          {
            // E22: dp = rho Q^2/(2 (C_dinf pi D_N h)^2) + 6 mu ln(D_land/D_N) Q/(pi h^3), solved for Q
            const double a = rho / (2 * std::pow(curtain_discharge_coefficient * curtain, 2));
            const double b = 6 * mu * std::log(g.land_diameter / DN) / (pi * h * h * h);
            s.flow_rate = 2 * dp / (b + std::sqrt(b * b + 4 * a * dp)); // the positive root, without cancellation
            s.discharge_coefficient = s.flow_rate / (curtain * ideal_velocity);
          }
        // a closed gap or no pressure difference: no flow, and C_dn -> 0 in the laminar limit
      }
    else
      {
        const auto c = paper::nozzle_discharge_coefficient(T); // E27 T-part
        s.discharge_coefficient = c.value;
        s.clamped = c.clamped;
        s.flow_rate = c.value * curtain * ideal_velocity; // E32
      }
    s.reynolds_number = nozzle_reynolds_number(DN, h, s.discharge_coefficient, ideal_velocity, nu); // E18
    s.flapper_force = momentum_force(dp, s.flow_rate);
    return s;
  }

  OrificeState PilotClosedForms::creeping_fixed_orifice(double dp) const
  {
    OrificeState s;
    const double D0 = g.fixed_orifice_diameter, A0 = 0.25 * pi * D0 * D0;
    const double ideal_velocity = std::sqrt(2 * dp / rho);
    s.reynolds_number = D0 * ideal_velocity / nu; // E17
    s.discharge_coefficient = s.reynolds_number / (4 * pi * (3 + 16 * g.fixed_orifice_length / (pi * D0)));
    s.flow_rate = s.discharge_coefficient * A0 * ideal_velocity;
    return s;
  }

  OrificeState PilotClosedForms::creeping_nozzle(double h, double dp, double bore_length) const
  {
    OrificeState s;
    const double rn = 0.5 * g.nozzle_diameter, rl = 0.5 * g.land_diameter;
    const double bore = 8 * mu * bore_length / (pi * std::pow(rn, 4)); // Hagen-Poiseuille
    const double land = 6 * mu * std::log(rl / rn) / (pi * h * h * h);  // radial flow between discs (E22's term)
    s.flow_rate = dp / (bore + land);
    const double ideal_velocity = std::sqrt(2 * dp / rho);
    s.discharge_coefficient = s.flow_rate / (pi * g.nozzle_diameter * h * ideal_velocity); // on the curtain
    s.reynolds_number = nozzle_reynolds_number(g.nozzle_diameter, h, s.discharge_coefficient, ideal_velocity, nu);
    return s;
  }

  double PilotClosedForms::momentum_force(double dp, double Q) const
  {
    // E23: bore pressure on the nozzle projection plus the momentum of the jet turned radial
    const double AN = 0.25 * pi * g.nozzle_diameter * g.nozzle_diameter;
    return dp * AN + rho * Q * Q / AN;
  }

  double PilotClosedForms::jet_force(double dp, double Q) const
  {
    return force_scale * momentum_force(dp, Q);
  }

  OrificeState PilotClosedForms::nozzle(double h, double dp) const
  {
    OrificeState s = momentum_nozzle(h, dp);
    s.flapper_force *= force_scale;
    s.clamped = s.clamped || force_clamped;
    return s;
  }
} // namespace servodrift
