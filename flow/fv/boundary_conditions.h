#pragma once
// Boundary conditions of the flow solver (doc/method.md, "Flow core", boundary conditions): the
// kinds a patch can have, their check against the mesh, and the values of u, v and p they give at
// the boundary faces.
#include "flow/fv/flow_state.h"

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace servodrift::flow
{
  struct BoundaryCondition
  {
    enum class Kind
    {
      wall,                 ///< no slip: the wall's velocity (default at rest)
      velocity_inlet,       ///< a given velocity profile
      total_pressure_inlet, ///< p_0 = p + rho u_n^2/2 given; the inflow normal to the face
      pressure_outlet,      ///< static pressure given for outflow (velocity from the inside); an
                            ///< inflow (backflow, entrainment) enters from rest at that pressure
      axis,                 ///< r = 0 of an axisymmetric domain
      symmetry,             ///< symmetry plane: no normal velocity, no shear
    } kind = Kind::wall;
    std::function<Vector2(const Vector2 &x)> velocity; ///< wall or inlet velocity at a boundary point [m/s]
    double pressure = 0;                                 ///< total or static pressure [Pa]
    /// Turbulence models: what an inflow brings, k = 3/2 (I u_n)^2 and epsilon = C_mu^(3/4) k^(3/2) / L
    double turbulence_intensity = 0.05; ///< I [1]
    double turbulence_length = 1e-4;    ///< L [m]
    /// Where set: the inflow's (k [m^2/s^2], epsilon [m^2/s^3]) at a boundary point, in place of
    /// the intensity and length (a measured inflow profile).
    std::function<std::pair<double, double>(const Vector2 &x)> turbulence_profile;

    static BoundaryCondition wall(Vector2 moving = Vector2::Zero());
    static BoundaryCondition velocity_inlet(std::function<Vector2(const Vector2 &)> profile);
    static BoundaryCondition total_pressure_inlet(double total_pressure);
    static BoundaryCondition pressure_outlet(double static_pressure);
    static BoundaryCondition axis();
    static BoundaryCondition symmetry();
  };

  /// The conditions of every patch of a mesh, resolved per face.
  class BoundaryConditions
  {
  public:
    using Kind = BoundaryCondition::Kind;

    /// Every boundary patch of the mesh needs a condition and every condition a patch; the flow
    /// needs a driver (an inlet or a moving wall) and an inlet needs an outlet; an axis needs an
    /// axisymmetric mesh. Throws InputError naming the mesh and the patch otherwise.
    BoundaryConditions(const FvMesh &mesh, const FluidProperties &fluid,
                       const std::map<std::string, BoundaryCondition> &conditions);

    Kind kind(std::size_t face) const { return face_kind[face]; }
    static bool is_pressure_kind(Kind k) { return k == Kind::pressure_outlet || k == Kind::total_pressure_inlet; }
    /// A total-pressure inlet or a pressure outlet: where p is given and the flux follows.
    bool is_pressure_boundary(std::size_t face) const { return is_pressure_kind(face_kind[face]); }
    bool has_pressure_boundary() const { return any_pressure_boundary; }
    /// Walls and velocity inlets: the velocity at the face [m/s].
    const Vector2 &prescribed_velocity(std::size_t face) const { return face_velocity[face]; }
    const BoundaryCondition &of_face(std::size_t face) const;
    const BoundaryCondition &of_patch(std::size_t patch) const { return patch_condition[patch]; }
    /// The mass inflow through the velocity inlets [kg/s per radian or unit depth]; 0 if there are none.
    double velocity_inlet_inflow() const { return inlet_inflow; }
    /// Writes the fluxes rho u_b.S of the velocity inlets into `flux'.
    void set_velocity_inlet_fluxes(std::vector<double> &flux) const;

    /// The total or static pressure of a pressure patch, and a new one (continuation) [Pa]; throws
    /// std::invalid_argument if `patch' is not a pressure boundary.
    double pressure(const std::string &patch) const;
    void set_pressure(const std::string &patch, double pressure);
    /// Every pressure patch's pressure, by name; and setting those of the list that are pressure
    /// patches of this mesh (continuation from another solver's fields).
    std::vector<std::pair<std::string, double>> pressures() const;
    void set_pressures(const std::vector<std::pair<std::string, double>> &pressures);
    /// Continuation between pressure levels: every pressure by s, the inflow speeds by sqrt(s).
    void scale(double s);

    /// Pressure boundaries: the normal velocity of an inflow from the fluxes F (< 0; 0 for an outflow).
    void update_inflow_speeds(const std::vector<double> &flux);
    /// The boundary face values of `state' from its cell fields: walls and velocity inlets their
    /// velocity, pressure boundaries an outflow's cell velocity or an inflow's normal speed, an axis
    /// no radial velocity, a symmetry plane no normal velocity. p_b: the given pressure at an
    /// outflow, p_0 - rho u_n^2/2 at an inflow; elsewhere extrapolated from the cell with its
    /// gradient, at least `pressure_floor' (the vapour pressure where cells cavitate).
    void update_values(FlowState &state, double pressure_floor) const;

  private:
    const FvMesh &mesh;
    double density;
    std::vector<BoundaryCondition> patch_condition; ///< per patch
    std::vector<Kind> face_kind;                    ///< per face (interior: unused)
    std::vector<Vector2> face_velocity;             ///< walls and velocity inlets, per face
    std::vector<double> inflow_speed;               ///< pressure boundaries, per face
    bool any_pressure_boundary = false;
    double inlet_inflow = 0;
    int pressure_patch(const std::string &patch) const; ///< throws unless a pressure boundary
  };
} // namespace servodrift::flow
