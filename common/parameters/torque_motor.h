#pragma once
#include "common/parameters/model_level.h"

#include <string>
namespace dealii { class ParameterHandler; }
namespace servodrift { class ParameterSource; struct ValveDescription; }

namespace servodrift
{
  /// Subsection "Torque motor" (model.md 1.2-1.5, 2.2, D4, D7, D10). Lengths are at the reference
  /// temperature T0; common/thermal_laws gives them at any temperature (E6-E8).
  struct TorqueMotorParameters
  {
    static constexpr const char *subsection = "Torque motor";
    ModelLevel model_level;  ///< reduced-order (the E3 circuit) or field (FEM, model.md 4.1)

    unsigned int turns_per_coil;  ///< N_c [1]
    bool series_aiding;           ///< false: push-pull, net MMF N_c i (D7); true: 2 N_c i
    double pivot_to_pole_distance; ///< a [m]
    double pole_face_width;       ///< w_p [m]
    double pole_face_length;      ///< l_p [m]
    bool fringing_expanded_area;  ///< A_g,eff = (w_p + g)(l_p + g) instead of w_p l_p (E2)

    double armature_thickness; ///< H_ar [m]
    double armature_width;     ///< [m]
    double armature_length;    ///< [m]
    double armature_height;    ///< H_a, datum to armature centre (E6, E7) [m]
    double lower_pole_height;  ///< H_c (E6) [m]
    double upper_pole_thickness; ///< H_c' (E7) [m]
    double upper_pole_tip_protrusion; ///< h_p (E7) [m]

    double magnet_length;   ///< l_m = H_m, along the magnetisation (E7, E8) [m]
    double magnet_width;    ///< [m]
    double magnet_depth;    ///< [m]
    unsigned int number_of_magnets; ///< magnets in parallel [1]
    double remanence;       ///< B_r0 at T0 [T]
    double remanence_temperature_coefficient; ///< alpha_Br [1/degC]
    double irreversible_loss;   ///< R_irr [1]
    double recoil_permeability; ///< mu_rm [1]
    double leakage_reluctance;  ///< R_l at T0 [A/Wb]
    double pole_piece_reluctance; ///< R_c [A/Wb]
    double armature_reluctance;   ///< R_a [A/Wb]

    double saturation_polarisation; ///< J_s of the 1J50 arctan B-H law [T]
    double initial_susceptibility;  ///< chi0 of the 1J50 arctan B-H law [1]
    double model_depth;             ///< w_d of the planar field model (D10) [m]
    bool paper_magnetic_spring;     ///< replace the linear magnetic spring by the paper's fit E25 (D2)
    // planar field model (D10, model.md 4.1; meshes/torque_motor.geo)
    unsigned int field_element_degree;   ///< FE_Q degree of A_z (1 or 2)
    double field_mesh_resolution;        ///< scales every element size by 1/resolution [1]
    unsigned int field_gap_layers;       ///< element layers across each working gap at resolution 1
    double field_magnet_width;           ///< in-plane width of each equivalent magnet block at T0 [m]
    double field_magnet_clearance;       ///< pole-tip outer edge to magnet block [m]
    double upper_plate_thickness;        ///< [m]
    double coil_inner_position;          ///< coil window from x = ... [m]
    double coil_outer_position;          ///< ... to x = ... [m]
    double coil_height;                  ///< [m]
    double coil_clearance;               ///< coil to armature [m]
    double air_boundary_radius;          ///< A_z = 0 on this circle [m]
    double newton_tolerance;             ///< residual reduction [1]
    double coil_resistance;         ///< per coil at 20 degC (voltage drive, 1.20) [Ohm]
    double coil_resistance_temperature_coefficient; ///< alpha_Cu [1/degC]
    double coil_inductance;         ///< L_c per coil (voltage drive) [H]
    bool voltage_drive;             ///< the amplifier imposes the coil voltage (coil state i) [-]

    static void declare_parameters(dealii::ParameterHandler &prm);
    void parse_parameters(ParameterSource &prm);

    /// Positive dimensions, remanence and leakage reluctance (E3, E8). Throws InputError naming the entry.
    void validate() const;
    /// Gaps open at every table temperature and motor angle (E6, E7); motor angles and currents that
    /// cover the secant K_m (C1) and the rated current. Throws InputError naming the entry.
    void validate(const ValveDescription &valve) const;
    /// The planar field model's parts without overlap (meshes/torque_motor.geo); for the field level.
    /// Throws InputError naming the entry.
    void validate_field_model() const;

    /// Net control MMF per ampere of differential current: N_c (push-pull) or 2 N_c (series) [1].
    double effective_turns() const { return series_aiding ? 2.0 * turns_per_coil : 1.0 * turns_per_coil; }
  };
} // namespace servodrift
