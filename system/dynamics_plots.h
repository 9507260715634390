#pragma once
// gnuplot plots of the dynamics (issue 23): the Bode plot of the brake pressure and the step
// responses, a curve per temperature coloured by it, the modes vs temperature, and the nonlinear
// sine study at the temperature nearest T0. Data (.dat) and scripts (.gp) in system/plots.
#include "common/valve_description.h"
#include "system/dynamics.h"
#include "system/plots.h"

#include <string>

namespace servodrift::system
{
  void write_dynamics_plots(const ValveDescription &valve, const DynamicsResults &results, const std::string &directory,
                            PlotFiles &files);
} // namespace servodrift::system
