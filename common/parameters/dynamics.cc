#include "common/parameters/dynamics.h"

#include "common/parameters/parameter_helpers.h"

namespace servodrift
{
  using namespace parameters;

  void DynamicsParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection(subsection);
    prm.declare_entry("Enabled", "true", Patterns::Bool(),
                      "Run the dynamics (modes, step and frequency responses) in `servodrift run'; "
                      "`servodrift dynamics' runs them whatever this says. [-]");
    prm.declare_entry("Bias", "0.5", Patterns::Double(-1, 1),
                      "Bias current of the linearisation, the small step and the sine inputs, as a "
                      "fraction of the rated current. At 0 RV-1's spool sits vented on its spring; the bias "
                      "must be large enough for it to regulate in its lap, where the linearisation means "
                      "something (doc/method.md, issue 23). [1]");
    prm.declare_entry("Small step", "0.05", Patterns::Double(1e-6, 1),
                      "Height of the small step from the bias, as a fraction of the rated current. [1]");
    prm.declare_entry("Step duration", "0", Patterns::Double(0, 100),
                      "Simulated time of each step response; 0 chooses it from the slowest mode of the "
                      "linearisation at the step's end point (12 time constants, at least 20 ms). [s]");
    prm.declare_entry("Minimum frequency", "1", Patterns::Double(1e-3, 1e6),
                      "Lowest frequency of the linear frequency response. [Hz]");
    prm.declare_entry("Maximum frequency", "5000", Patterns::Double(1e-3, 1e6),
                      "Highest frequency of the linear frequency response; above the minimum. [Hz]");
    prm.declare_entry("Frequency points", "200", Patterns::Integer(2, 100000),
                      "Points of the linear frequency response, log-spaced. [1]");
    prm.declare_entry("Sine frequencies", "10, 20, 50, 100, 200, 300, 500, 700, 1000, 2000",
                      double_list(1e-3, 1e6, 1),
                      "Frequencies of the nonlinear sine responses, strictly increasing. [Hz]");
    prm.declare_entry("Sine check amplitude", "0.01", Patterns::Double(1e-9, 1),
                      "Largest amplitude of the small-signal sine that checks the linearisation, as a "
                      "fraction of the rated current; at each frequency it is lowered until the linear "
                      "excursions of spool and flapper stay within `Linearity margin' of their edges. "
                      "[1]");
    prm.declare_entry("Linearity margin", "0.1", Patterns::Double(1e-6, 1),
                      "Largest linear excursion of the small-signal sine as a fraction of the distance "
                      "from the bias to the nearest edge: the spool's lap edges (x_ov -+ x_v) and the "
                      "nozzles (x0 -+ x_f). [1]");
    prm.declare_entry("Sine amplitudes", "0.05, 0.25, 1", double_list(1e-9, 100, 1),
                      "Amplitudes of the large-signal sine study around the bias, as fractions of the "
                      "rated current, strictly increasing; bias +- amplitude must lie within `Sweeps/"
                      "Motor currents'. One that drives the flapper onto a nozzle is allowed: the "
                      "contact saturates it and the results say so. [1]");
    prm.declare_entry("Large-signal temperatures", "5", Patterns::Integer(1, 100000),
                      "How many drift temperatures the large-signal study (`Sine amplitudes', swept up and "
                      "down) runs at: the two ends and the others evenly spread between them (all if "
                      "there are fewer). The linear analyses, the steps and the sine check run at every "
                      "drift temperature; the study is the dynamics' costliest part (doc/performance.md). "
                      "[1]");
    prm.declare_entry("Cold-start temperatures", "-55, -40, -20, 40", double_list(-273.15, 1000, 0),
                      "Temperatures of the cold-soak start: the valve at rest at that temperature (every "
                      "pressure at return), supply and `Cold-start current' applied at t = 0; the report "
                      "gives the time until p_B stays within 2 % of its final value and its overshoot. "
                      "Strictly increasing; one beyond the table temperatures is skipped and named in the "
                      "report; empty for none. [degC]");
    prm.declare_entry("Cold-start current", "1", Patterns::Double(0, 100),
                      "Command of the cold-soak start as a fraction of the rated current (1: the brake "
                      "applied fully). [1]");
    prm.declare_entry("Samples per period", "64", Patterns::Integer(8, 100000),
                      "Samples per period of a sine response from which its harmonics are computed. [1]");
    prm.declare_entry("Maximum periods", "40", Patterns::Integer(2, 100000),
                      "Periods a sine response may take to become periodic (its state recurs after one "
                      "period, or after m <= 32 periods for a sub-harmonic, within `Periodic tolerance'); "
                      "one that does not is reported as not periodic. Newton steps on the period map "
                      "(shooting) shorten a slow approach; the periods their Jacobians take are not "
                      "counted. [1]");
    prm.declare_entry("Periodic tolerance", "1e-3", Patterns::Double(1e-12, 1),
                      "Largest change of the state over one period (or m periods), in each state's scale, "
                      "relative to the motion of the outputs, of a periodic steady state; it bounds the "
                      "error of the harmonics to about as much. [1]");
    prm.declare_entry("Relative tolerance", "1e-6", Patterns::Double(1e-14, 1e-2),
                      "Relative local error tolerance of the time integration (CVODE, BDF), applied to "
                      "the motion about the operating point each analysis starts from. [1]");
    prm.declare_entry("Absolute tolerance", "1e-8", Patterns::Double(1e-16, 1e-2),
                      "Absolute local error tolerance of the time integration, as a fraction of each "
                      "state's scale (x0/r, p_s - p_r, the stroke limit, the rated current). [1]");
    prm.declare_entry("Maximum steps", "1000000", Patterns::Integer(100, 100000000),
                      "Most internal steps of one integration (a step response, a sine response, a chunk "
                      "of the start-up) before it stops with an error naming temperature, time and the "
                      "entries of the state that held the steps down. A step costs about 0.2 ms: 1e6 "
                      "steps about 3 min, the top of the range about 5 h. [1]");
    prm.declare_entry("Fixed-time study", "false", Patterns::Bool(),
                      "model.md C9: integrate the start-up of the valve (supply switched on with every "
                      "pressure at return, armature and spool centred) at each drift temperature, with "
                      "and without each of `Fixed-time deviation angles', and read the drift measures at "
                      "fixed times (`Reading times'), to test whether the paper read its dynamic model "
                      "before the steady state. [-]");
    prm.declare_entry("Fixed-time deviation angles", "0.0003, 1", double_list(-10, 10, 1),
                      "Deviation angles theta_d of the fixed-time study, by the valve's `Offsets' "
                      "convention: the paper's 1 deg, and 0.0003 deg, about the effective offset its "
                      "small deviations imply (1.19, C9), where the valve is not saturated. [deg]");
    prm.declare_entry("Reading times", "1e-4, 2e-4, 5e-4, 1e-3, 2e-3, 5e-3, 0.01, 0.02, 0.05, 0.1, 0.2, 0.5, 1",
                      double_list(1e-9, 1e3, 1),
                      "Times after start-up at which the fixed-time study reads the drift measures, "
                      "strictly increasing. [s]");
    prm.leave_subsection();
  }
} // namespace servodrift
