#include "common/parameters/pilot_stage.h"

#include "common/parameters/parameter_source.h"

namespace servodrift
{
  using namespace parameters;

  void PilotStageParameters::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    model_level = parse_model_level(prm.get("Model level"));
    fixed_orifice_diameter = prm.get_double("Fixed orifice diameter");
    fixed_orifice_length = prm.get_double("Fixed orifice length");
    nozzle_diameter = prm.get_double("Nozzle diameter");
    land_diameter = prm.get_double("Land diameter");
    null_gap = prm.get_double("Null gap");
    nozzle_seat_span = prm.get_double("Nozzle seat span");
    nozzle_length = prm.get_double("Nozzle length");
    nozzle_discharge_coefficient = prm.get_double("Nozzle discharge coefficient");
    control_cavity_volume = prm.get_double("Control cavity volume");
    field_resolution = prm.get_double("Field mesh resolution");
    field_grid_sequencing = prm.get_bool("Field grid sequencing");
    field_continuation_ratio = prm.get_double("Field continuation ratio");
    field_turbulent_viscosity_limit = prm.get_double("Field turbulent viscosity limit");
    field_plenum_size = prm.get_double("Field plenum size");
    field_chamber_length = prm.get_double("Field chamber length");
    field_outlet_radius = prm.get_double("Field outlet radius");
    field_cavitation = prm.get_bool("Field cavitation");
    field_time_average = prm.get_bool("Field time average");
    field_time_step_courant = prm.get_double("Field time step Courant number");
    field_time_step_iterations = static_cast<unsigned int>(prm.get_integer("Field time step iterations"));
    field_time_step_halvings = static_cast<unsigned int>(prm.get_integer("Field time step halvings"));
    field_time_steps = static_cast<unsigned int>(prm.get_integer("Field time steps"));
    field_time_steps_limit = static_cast<unsigned int>(prm.get_integer("Field time steps limit"));
    field_averaged_fraction = prm.get_double("Field averaged fraction");
    field_time_average_uncertainty_limit = prm.get_double("Field time average uncertainty limit");
    auto model_of = [&](const char *entry) {
      const std::string m = prm.get(entry);
      return m == "laminar"                  ? FlowModel::laminar :
             m == "k-epsilon"                ? FlowModel::k_epsilon :
             m == "k-epsilon-launder-sharma" ? FlowModel::k_epsilon_launder_sharma :
             m == "k-omega-sst"              ? FlowModel::k_omega_sst :
                                               FlowModel::automatic;
    };
    fixed_orifice_flow_model = model_of("Fixed orifice flow model");
    fixed_orifice_transition_reynolds = prm.get_double("Fixed orifice transition Reynolds number");
    nozzle_flow_model = model_of("Nozzle flow model");
    nozzle_transition_reynolds = prm.get_double("Nozzle transition Reynolds number");
    nozzle_stall_window = static_cast<unsigned int>(prm.get_integer("Nozzle stall window"));
    model_form_alternatives.clear();
    for (const std::string &name : split_list(prm.get("Model-form alternatives")))
      model_form_alternatives.push_back(name);
    const std::string bore = prm.get("Bore sensitivity");
    bore_sensitivity = bore == "on" ? BoreSensitivity::on : bore == "off" ? BoreSensitivity::off : BoreSensitivity::automatic;
    bore_sensitivity_step = prm.get_double("Bore sensitivity step");
    fixed_orifice_law =
      prm.get("Fixed orifice law") == "paper-fit" ? OrificeLaw::paper_fit : OrificeLaw::lichtarowicz;
    nozzle_law = prm.get("Nozzle law") == "paper-fit" ? NozzleLaw::paper_fit : NozzleLaw::curtain;
    flapper_force_law = prm.get("Flapper force law") == "paper-table" ? FlapperForceLaw::paper_table :
                                                                        FlapperForceLaw::momentum;
    prm.leave_subsection();
  }
} // namespace servodrift
