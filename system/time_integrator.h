#pragma once
// Time integration of y' = F(t, y) with SUNDIALS CVODE: variable-order BDF (stiff: the nozzle
// contacts and the cavity compressibilities make the valve's equations stiff), Newton iterations
// with a dense direct solver and CVODE's difference-quotient Jacobian, per-component absolute
// tolerances. Every CVODE return flag is checked; a failure (or an exception thrown by F) becomes a
// std::runtime_error that names the case (`context', e.g. the temperature) and the time reached.
// The SUNDIALS types stay in the .cc file.
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace servodrift::system
{
  class TimeIntegrator
  {
  public:
    /// F(t, y, ydot); it may throw (TableRangeError, ...): the integration stops and rethrows.
    using RightHandSide = std::function<void(double t, const double *y, double *ydot)>;
    /// J = dF/dy at (t, y), given F(t, y); column-major n x n. Empty: CVODE's difference quotients.
    using Jacobian = std::function<void(double t, const double *y, const double *ydot, double *jacobian)>;

    struct Settings
    {
      double relative_tolerance = 1e-8;
      std::vector<double> absolute_tolerances; ///< one per component
      long maximum_steps = 1000000;            ///< internal steps per advance_to() or integrate()
      int maximum_order = 5;                   ///< of the BDF formulas
      bool stability_limit_detection = true;   ///< CVODE's BDF stability limit detection (STALD)
      Jacobian jacobian;                       ///< empty: CVODE's own difference quotients
      /// What sets the speed of a component, for the message when the steps run out (the
      /// component whose local error holds the step down); empty: its index
      std::function<std::string(std::size_t component)> describe_component;
    };

    struct Statistics
    {
      long steps = 0, rhs_evaluations = 0, jacobian_evaluations = 0, error_test_failures = 0;
      long nonlinear_iterations = 0, convergence_failures = 0;
      int last_order = 0;
    };

    TimeIntegrator(std::size_t size, RightHandSide rhs, Settings settings, std::string context);
    ~TimeIntegrator();
    TimeIntegrator(const TimeIntegrator &) = delete;
    TimeIntegrator &operator=(const TimeIntegrator &) = delete;

    /// (Re)starts at t0 from y0 (a new initial value problem: the order and step start afresh,
    /// as they must after a discontinuity of the input).
    void start(double t0, const std::vector<double> &y0);
    /// Integrates to t (never past it) and returns y(t).
    const std::vector<double> &advance_to(double t);
    /// One internal step, not past t_limit; returns the time reached. y() is the state there.
    double step(double t_limit);
    /// The solution at t within the last internal step (CVODE's interpolating polynomial).
    std::vector<double> interpolate(double t) const;
    /// Integrates to t_end in internal steps; after each step, on_step(t_previous, t) may query
    /// interpolate() on [t_previous, t] and return false to stop early. Returns the time reached.
    double integrate(double t_end, const std::function<bool(double t_previous, double t)> &on_step);

    double time() const { return t_now; }
    const std::vector<double> &y() const { return y_now; }
    Statistics statistics() const;

    struct Cvode; ///< the SUNDIALS objects (time_integrator.cc)

  private:
    std::unique_ptr<Cvode> cvode;
    RightHandSide rhs;
    Jacobian jacobian;
    long maximum_steps;
    std::function<std::string(std::size_t)> describe_component;
    std::string context;
    double t_now = 0;
    std::vector<double> y_now;

    [[noreturn]] void fail(int flag, const char *call) const;
    /// Throws once a call has taken more than maximum_steps internal steps.
    void count(long steps) const;
  };
} // namespace servodrift::system
