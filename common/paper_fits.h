#pragma once
// The paper's own fitted laws for the pilot stage (model.md D2, 1.11, section 3 items 8-10), used
// only by the paper preset. Each is used inside its validity window and clamped to the window's end
// outside it, with a flag (C6).
namespace servodrift::paper
{
  struct ClampedValue
  {
    double value;
    bool clamped;
  };

  /// E26: C_d0 = 4.196e-13 Re^3 - 1.226e-8 Re^2 + 1.202e-4 Re + 0.3875, Re_0 in [0.1, 1.2] x 9.74e3.
  ClampedValue fixed_orifice_discharge_coefficient(double reynolds_number);

  /// E27, T-part: C_dn = 0.5841 + 3.49e-4 T - 2.26e-6 T^2 (maximum at 77 degC), T in [40, 120] degC.
  ClampedValue nozzle_discharge_coefficient(double temperature);

  /// Section 3 item 10: the paper's flow-force stiffness K_f(T) [N/m] (paper-fidelity table 40..120
  /// degC, monotone cubic interpolation in between).
  ClampedValue flow_force_stiffness(double temperature);
} // namespace servodrift::paper
