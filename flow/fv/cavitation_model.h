#pragma once
// Cavitation, equilibrium and mass-conserving (doc/method.md, "Cavitation"): no pressure below the
// vapour pressure p_cav. Each cell is liquid (liquid fraction gamma = 1, p >= p_cav) or cavitating
// (p = p_cav, gamma < 1); the mixture density rho (gamma + (1 - gamma) r), r the vapour density
// ratio, carries the mass. A face carries the mixture density of its upwind cell (an inflow from a
// boundary is liquid), so the mixture's mass flux through a face is m F with F = rho u.S the flux at
// the liquid's density and m = gamma + (1 - gamma) r of the upwind cell.
#include "flow/fv/flow_state.h"
#include "flow/fv/fv_mesh.h"

#include <vector>

namespace servodrift::flow
{
  class CavitationModel
  {
  public:
    CavitationModel(const FvMesh &mesh, double vapour_density_ratio);

    /// From here on cells cavitate below p_cav [Pa, in the solver's gauge].
    void enable(double vapour_pressure);
    bool enabled() const { return on; }
    /// The lowest pressure a cell can have: p_cav, or none without cavitation [Pa].
    double pressure_floor() const { return floor; }

    /// m = gamma + (1 - gamma) r of a cell: its mixture density over the liquid's [1]; 1 without
    /// cavitation, as for the faces (fields given with a liquid fraction before the model is on
    /// carry liquid fluxes: their mixture's ratio made the Courant step 120 times too small).
    double mixture_ratio(std::size_t cell) const
    {
      if (!on)
        return 1.0;
      return gamma[cell] + (1 - gamma[cell]) * vapour_ratio;
    }
    /// m of every cell.
    std::vector<double> mixture_ratios() const
    {
      std::vector<double> m(gamma.size());
      for (std::size_t c = 0; c < m.size(); ++c)
        m[c] = mixture_ratio(c);
      return m;
    }
    /// The mixture density ratio that face f carries with the flux F (upwind; an inflow is liquid;
    /// 1 without cavitation).
    double face_mixture_ratio(std::size_t f, double F) const
    {
      if (!on)
        return 1.0;
      if (mesh.neighbour[f] < 0)
        return F >= 0 ? mixture_ratio(mesh.owner[f]) : 1.0;
      return mixture_ratio(F >= 0 ? mesh.owner[f] : static_cast<unsigned int>(mesh.neighbour[f]));
    }
    /// The mixture's mass flux m F through each face from the fluxes F [kg/s per radian].
    void update_mixture_flux(const std::vector<double> &flux);
    /// The flux that convects: the mixture's mass flux with cavitation, F without.
    const std::vector<double> &convecting_flux(const std::vector<double> &flux) const { return on ? mixture_flux : flux; }

    /// The liquid fraction of the cavitating cells from their mixture mass balance with the new
    /// fluxes; a cell whose inflow would need gamma >= 1 is liquid again. With a time step (`time'
    /// set) the balance holds the change of the cell's mass as well, rho V dm/dt, and a cell that the
    /// last pressure correction made cavitate stays so for this iteration (`entered').
    void update_liquid_fraction(const std::vector<double> &flux, const TimeLevel *time = nullptr, double density = 0);
    /// A cell's new pressure: a cavitating cell holds p_cav, and a liquid one that would be stretched
    /// below it cavitates.
    void set_cell_pressure(std::vector<double> &p, std::size_t cell, double pressure)
    {
      if (on && (cavitating[cell] || pressure < floor))
        {
          if (!cavitating[cell])
            entered[cell] = 1;
          p[cell] = floor, cavitating[cell] = 1;
        }
      else
        p[cell] = pressure;
    }
    bool cell_cavitates(std::size_t cell) const { return on && cavitating[cell]; }
    std::size_t n_cavitating() const;

    std::vector<double> gamma;     ///< liquid volume fraction per cell [1]
    std::vector<char> cavitating;  ///< per cell
    std::vector<double> mixture_flux; ///< m F per face [kg/s per radian]

  private:
    /// Cells that the last pressure correction made cavitate (set_cell_pressure), until the next
    /// update_liquid_fraction: their fluxes were corrected as a liquid cell's, so they balance to
    /// round-off, and `in >= out' would return the cell to the liquid at p_cav with the correction
    /// that stretched it lost. Such a cell lay on p_cav every iteration with the same imbalance: the
    /// capped steps of the hot cavitating orifice (doc/validation.md, "Robustness"). Time steps only:
    /// without the storage term a steady iteration's liquid fraction follows the unconverged fluxes
    /// of that next iteration, and Launder-Sharma's steady orifice at 20.6 MPa diverged with it.
    std::vector<char> entered;
    const FvMesh &mesh;
    double vapour_ratio;
    bool on = false;
    double floor;
  };
} // namespace servodrift::flow
