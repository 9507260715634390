#include "common/parameters/parameter_source.h"
#include "common/parameters/pilot_stage.h"

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
    control_cavity_volume = prm.get_double("Control cavity volume");
    reduced_order.parse_parameters(prm);
    field_mesh.parse_parameters(prm);
    field_solution.parse_parameters(prm);
    time_average.parse_parameters(prm);
    bore_sensitivity.parse_parameters(prm);
    prm.leave_subsection();
  }

  void PilotReducedOrderParameters::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    fixed_orifice_law =
      prm.get("Fixed orifice law") == "paper-fit" ? OrificeLaw::paper_fit : OrificeLaw::lichtarowicz;
    nozzle_law = prm.get("Nozzle law") == "paper-fit" ? NozzleLaw::paper_fit : NozzleLaw::curtain;
    nozzle_discharge_coefficient = prm.get_double("Nozzle discharge coefficient");
    flapper_force_law = prm.get("Flapper force law") == "paper-table" ? FlapperForceLaw::paper_table :
                                                                        FlapperForceLaw::momentum;
    prm.leave_subsection();
  }

  void BoreSensitivityParameters::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    const std::string choice = prm.get("Tables");
    tables = choice == "on" ? Tables::on : choice == "off" ? Tables::off : Tables::automatic;
    step = prm.get_double("Step");
    prm.leave_subsection();
  }

  void PilotFieldMeshParameters::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    resolution = prm.get_double("Resolution");
    grid_sequencing = prm.get_bool("Grid sequencing");
    plenum_size = prm.get_double("Plenum size");
    chamber_length = prm.get_double("Chamber length");
    outlet_radius = prm.get_double("Outlet radius");
    prm.leave_subsection();
  }

  void PilotFieldSolutionParameters::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
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
    cavitation = prm.get_bool("Cavitation");
    continuation_ratio = prm.get_double("Continuation ratio");
    turbulent_viscosity_limit = prm.get_double("Turbulent viscosity limit");
    nozzle_stall_window = static_cast<unsigned int>(prm.get_integer("Nozzle stall window"));
    model_form_alternatives.clear();
    for (const std::string &name : split_list(prm.get("Model-form alternatives")))
      model_form_alternatives.push_back(name);
    prm.leave_subsection();
  }

  void PilotTimeAverageParameters::parse_parameters(ParameterSource &prm)
  {
    prm.enter_subsection(subsection);
    enabled = prm.get_bool("Enabled");
    courant_number = prm.get_double("Courant number");
    step_iterations = static_cast<unsigned int>(prm.get_integer("Step iterations"));
    step_halvings = static_cast<unsigned int>(prm.get_integer("Step halvings"));
    steps = static_cast<unsigned int>(prm.get_integer("Steps"));
    steps_limit = static_cast<unsigned int>(prm.get_integer("Steps limit"));
    averaged_fraction = prm.get_double("Averaged fraction");
    uncertainty_limit = prm.get_double("Uncertainty limit");
    prm.leave_subsection();
  }
} // namespace servodrift
