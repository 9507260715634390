#pragma once
// The pilot stage's field level (model.md 4.2, D11): its meshes, the settings of a steady case's
// solution and of the time average of a case without one. Subsections of "Pilot stage"; together
// with "Flow solver" they are what the finite-volume cases read (flow/pilot/pilot_field.h), not the whole
// valve description.
#include <string>
#include <vector>
namespace dealii { class ParameterHandler; }
namespace servodrift { class ParameterSource; }

namespace servodrift
{
  /// Subsection "Pilot stage/Field mesh" (meshes/fixed_orifice.geo, meshes/nozzle_flapper.geo)
  struct PilotFieldMeshParameters
  {
    static constexpr const char *subsection = "Field mesh";
    double resolution;     ///< multiplies every cell count [1]
    bool grid_sequencing;  ///< a fine case from rest starts from the half-resolution solution
    double plenum_size;    ///< orifice plenum radius and length / bore radius [1]
    double chamber_length; ///< orifice downstream chamber length / bore radius [1]
    double outlet_radius;  ///< nozzle-flapper outlet radius / land radius [1]

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);
  };

  /// Subsection "Pilot stage/Field solution": the flow model of each case and its solution path
  struct PilotFieldSolutionParameters
  {
    static constexpr const char *subsection = "Field solution";
    /// flow model of a field case: automatic picks laminar below the transition Reynolds number
    /// (ideal velocity: E17 for the orifice, 2h sqrt(2 dp/rho)/nu for the nozzle) and k-epsilon above
    enum class FlowModel { automatic, laminar, k_epsilon, k_epsilon_launder_sharma, k_omega_sst };
    FlowModel fixed_orifice_flow_model;
    double fixed_orifice_transition_reynolds; ///< [1]
    FlowModel nozzle_flow_model;
    double nozzle_transition_reynolds;        ///< [1]
    bool cavitation;                  ///< cases model cavitation at the vapour pressure
    double continuation_ratio;        ///< largest ratio of successive pressure levels of a solution path [1]
    double turbulent_viscosity_limit; ///< largest mu_t/mu on a solution path / ideal Re [1]
    unsigned int nozzle_stall_window; ///< Flow solver's stall window for the nozzle cases [1]
    /// other flow models whose tables the flow stage also computes (model-form uncertainty); each by
    /// its name in the tables' file names (`laminar': the automatic switch)
    std::vector<std::string> model_form_alternatives;

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);
  };

  /// Subsection "Pilot stage/Time average": a case without a steady solution marched in time and
  /// reported by its mean (flow/pilot/pilot_field_time_average.h)
  struct PilotTimeAverageParameters
  {
    static constexpr const char *subsection = "Time average";
    bool enabled;                  ///< false: such a case is flagged and the reduced order stands in
    double courant_number;         ///< Courant number of the time step [1]
    unsigned int step_iterations;  ///< SIMPLEC iterations of a time step at most
    unsigned int step_halvings;    ///< marches again at half the Courant number if too many steps capped
    unsigned int steps;            ///< time steps marched first
    unsigned int steps_limit;      ///< time steps at most, lengthened for the mean's uncertainty
    double averaged_fraction;      ///< the last fraction of them that is averaged [1]
    double uncertainty_limit;      ///< largest relative standard error of a usable mean [1]

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);
    /// The steps' limit at least the first count. Throws InputError naming the entry.
    void validate() const;
  };
} // namespace servodrift
