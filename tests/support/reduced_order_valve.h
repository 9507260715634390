#pragma once
// RV-1 (with overrides) and its valve model on the reduced-order tables, static and dynamic: what the
// system-level tests start from.
#include "system/valve_dynamics.h"
#include "system/valve_model.h"
#include "tests/support/test_support.h"

#include <string>
#include <vector>

namespace servodrift::test
{
  struct ReducedOrderValve
  {
    ValveDescription description; ///< test::valve(overrides)
    std::string tables;           ///< the directory of its reduced-order tables
    system::ValveModel model;     ///< the valve on those tables
    explicit ReducedOrderValve(const std::vector<std::string> &overrides = {});
    /// Its dynamic model (E29-E37) at T [degC], with the parts held and the offsets given
    system::ValveDynamics dynamics(double T, system::HeldParts held = {}, const system::Offsets &offsets = {}) const;
  };

  /// The valve of `overrides', made once per test program and shared by the tests that ask for
  /// the same overrides (its tables take seconds to make)
  const ReducedOrderValve &shared_reduced_order_valve(const std::vector<std::string> &overrides = {});

  /// The largest |F_k|/(scale_k w_ref) of a state under a command: how far it is from rest, in each
  /// state's scale per armature time unit (w_ref = sqrt(K_a/J_a)).
  double scaled_rates(const system::ValveDynamics &d, const system::ValveState &s, double command);
} // namespace servodrift::test
