#pragma once
#include "common/parameters/model_level.h"

#include <string>
#include <vector>
namespace dealii { class ParameterHandler; }
namespace servodrift { class ParameterSource; struct ValveDescription; }

namespace servodrift
{
  /// Subsection "Pilot stage": fixed orifices, nozzles and the nozzle-flapper gap (model.md 1.8-1.10,
  /// 1.14, 2.6, D11). Dimensions at the reference temperature T0.
  struct PilotStageParameters
  {
    static constexpr const char *subsection = "Pilot stage";
    ModelLevel model_level;         ///< reduced-order (E21-E23) or field (finite volumes, 4.2)
    double fixed_orifice_diameter;  ///< D_0 [m]
    double fixed_orifice_length;    ///< l_0 [m]
    double nozzle_diameter;         ///< D_N [m]
    double land_diameter;           ///< D_land, outer diameter of the nozzle tip [m]
    double null_gap;                ///< x0 [m]
    double nozzle_seat_span;        ///< body span between the two nozzle seats [m]
    double nozzle_length;           ///< length of each nozzle from its seat to its tip [m]
    double nozzle_discharge_coefficient; ///< C_d,inf of the curtain orifice (E22) [1]
    double control_cavity_volume;   ///< V_0 (E33; dynamics) [m^3]

    enum class OrificeLaw { lichtarowicz, paper_fit };       ///< E21 or E26 (D2)
    enum class NozzleLaw { curtain, paper_fit };             ///< E22 or E27 T-part (D2)
    enum class FlapperForceLaw { momentum, paper_table };    ///< E23 or section 3 item 10 (D2)
    // field level (meshes/fixed_orifice.geo, meshes/nozzle_flapper.geo)
    double field_resolution;        ///< multiplies every cell count [1]
    bool field_grid_sequencing;     ///< a fine case from rest starts from the half-resolution solution
    double field_continuation_ratio; ///< largest ratio of successive pressure levels of a solution path [1]
    double field_turbulent_viscosity_limit; ///< largest mu_t/mu on a solution path / ideal Re [1]
    double field_plenum_size;       ///< orifice plenum radius and length / bore radius [1]
    double field_chamber_length;    ///< orifice downstream chamber length / bore radius [1]
    double field_outlet_radius;     ///< nozzle-flapper outlet radius / land radius [1]
    bool field_cavitation;          ///< field cases model cavitation at the vapour pressure
    bool field_time_average;        ///< a case without a steady solution is reported by its time average
    double field_time_step_courant; ///< Courant number of the time step of a time average [1]
    unsigned int field_time_step_iterations; ///< SIMPLEC iterations of a time step at most
    unsigned int field_time_step_halvings; ///< marches again at half the Courant number if too many steps capped
    unsigned int field_time_steps;  ///< time steps of a time average, first
    unsigned int field_time_steps_limit; ///< time steps of a time average at most, lengthened for its uncertainty
    double field_averaged_fraction; ///< the last fraction of them that is averaged [1]
    double field_time_average_uncertainty_limit; ///< largest relative standard error of a usable time-averaged mean [1]
    /// flow model of a field case: automatic picks laminar below the transition Reynolds number
    /// (ideal velocity: E17 for the orifice, 2h sqrt(2 dp/rho)/nu for the nozzle) and k-epsilon above
    enum class FlowModel { automatic, laminar, k_epsilon, k_epsilon_launder_sharma, k_omega_sst };
    FlowModel fixed_orifice_flow_model;
    double fixed_orifice_transition_reynolds; ///< [1]
    FlowModel nozzle_flow_model;
    double nozzle_transition_reynolds;        ///< [1]
    unsigned int nozzle_stall_window;         ///< Flow solver's stall window for the nozzle cases [1]
    /// field level: other flow models whose tables the flow stage also computes (model-form
    /// uncertainty); each by its name in the tables' file names (`laminar': the automatic switch)
    std::vector<std::string> model_form_alternatives;

    /// whether the flow stage tabulates the flows at wider bores (automatic: when a study needs them
    /// at the field level; ValveDescription::needs_bore_tables)
    enum class BoreSensitivity { automatic, on, off };
    BoreSensitivity bore_sensitivity;
    double bore_sensitivity_step; ///< [m]

    OrificeLaw fixed_orifice_law;
    NozzleLaw nozzle_law;
    FlapperForceLaw flapper_force_law;

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);

    /// The time steps' limit of a time average at least its first count. Throws InputError naming the entry.
    void validate_time_average() const;
    /// Positive dimensions, x0 <= D_N/4 (E32), D_land > D_N (E22). Throws InputError naming the entry.
    void validate() const;
    /// The null gap open at every table temperature (2.3). Throws InputError naming the entry.
    void validate(const ValveDescription &valve) const;
    /// V_0 above the volume the spool end sweeps (E33). Throws InputError naming the entry.
    void validate_dynamic_model(const ValveDescription &valve) const;
  };
} // namespace servodrift
