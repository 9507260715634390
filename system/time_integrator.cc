#include "system/time_integrator.h"

#include "common/error.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cmath>
#include <exception>
#include <stdexcept>

namespace servodrift::system
{
  /// The SUNDIALS objects of one integrator, and what the C callbacks hand back to C++.
  struct TimeIntegrator::Cvode
  {
    SUNContext context = nullptr;
    N_Vector y = nullptr, absolute_tolerances = nullptr;
    SUNMatrix matrix = nullptr;
    SUNLinearSolver solver = nullptr;
    void *memory = nullptr;
    const RightHandSide *rhs = nullptr;
    const Jacobian *jacobian = nullptr;
    std::exception_ptr error; ///< thrown by F: rethrown after CVODE returns
    std::string message;      ///< CVODE's own error message

    ~Cvode()
    {
      CVodeFree(&memory);
      SUNLinSolFree(solver);
      SUNMatDestroy(matrix);
      N_VDestroy(absolute_tolerances);
      N_VDestroy(y);
      SUNContext_Free(&context);
    }
  };

  namespace
  {
    int evaluate_rhs(realtype t, N_Vector y, N_Vector ydot, void *data)
    {
      auto *c = static_cast<TimeIntegrator::Cvode *>(data);
      try
        {
          (*c->rhs)(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
        }
      catch (const TableRangeError &)
        {
          // recoverable: a trial step past a contact may query beyond a table where the solution
          // does not go; CVODE retries with a smaller step, and fails only if the solution goes there
          c->error = std::current_exception();
          return 1;
        }
      catch (...)
        {
          c->error = std::current_exception();
          return -1; // unrecoverable: CVODE returns at once
        }
      const sunindextype n = N_VGetLength(ydot);
      const double *d = N_VGetArrayPointer(ydot);
      for (sunindextype k = 0; k < n; ++k)
        if (!std::isfinite(d[k]))
          return 1; // recoverable: CVODE retries with a smaller step
      return 0;
    }

    int evaluate_jacobian(realtype t, N_Vector y, N_Vector fy, SUNMatrix J, void *data, N_Vector, N_Vector, N_Vector)
    {
      auto *c = static_cast<TimeIntegrator::Cvode *>(data);
      try
        {
          (*c->jacobian)(t, N_VGetArrayPointer(y), N_VGetArrayPointer(fy), SUNDenseMatrix_Data(J));
        }
      catch (...)
        {
          c->error = std::current_exception();
          return -1;
        }
      return 0;
    }

    void keep_message(int, const char *module, const char *function, char *message, void *data)
    {
      static_cast<TimeIntegrator::Cvode *>(data)->message =
        std::string(module) + " " + function + ": " + message;
    }
  } // namespace

  TimeIntegrator::TimeIntegrator(std::size_t n, RightHandSide rhs_, Settings settings, std::string context_)
    : cvode(std::make_unique<Cvode>())
    , rhs(std::move(rhs_))
    , jacobian(std::move(settings.jacobian))
    , maximum_steps(settings.maximum_steps)
    , describe_component(std::move(settings.describe_component))
    , context(std::move(context_))
    , y_now(n, 0.0)
  {
    auto &c = *cvode;
    c.rhs = &rhs;
    c.jacobian = &jacobian;
    if (SUNContext_Create(nullptr, &c.context) != 0)
      throw std::runtime_error(context + ": SUNDIALS context could not be created");
    const auto size = static_cast<sunindextype>(n);
    c.y = N_VNew_Serial(size, c.context);
    c.absolute_tolerances = N_VNew_Serial(size, c.context);
    if (!c.y || !c.absolute_tolerances || settings.absolute_tolerances.size() != n)
      throw std::runtime_error(context + ": CVODE vectors could not be made");
    for (std::size_t k = 0; k < n; ++k)
      N_VGetArrayPointer(c.absolute_tolerances)[k] = settings.absolute_tolerances[k];
    c.memory = CVodeCreate(CV_BDF, c.context);
    if (!c.memory)
      throw std::runtime_error(context + ": CVodeCreate failed");
    int flag = CVodeSetErrHandlerFn(c.memory, keep_message, &c);
    if (flag == CV_SUCCESS)
      flag = CVodeInit(c.memory, evaluate_rhs, 0.0, c.y);
    if (flag != CV_SUCCESS)
      fail(flag, "CVodeInit");
    if ((flag = CVodeSetUserData(c.memory, &c)) != CV_SUCCESS)
      fail(flag, "CVodeSetUserData");
    if ((flag = CVodeSVtolerances(c.memory, settings.relative_tolerance, c.absolute_tolerances)) != CV_SUCCESS)
      fail(flag, "CVodeSVtolerances");
    c.matrix = SUNDenseMatrix(size, size, c.context);
    c.solver = SUNLinSol_Dense(c.y, c.matrix, c.context);
    if (!c.matrix || !c.solver)
      throw std::runtime_error(context + ": the dense linear solver could not be made");
    if ((flag = CVodeSetLinearSolver(c.memory, c.solver, c.matrix)) != CV_SUCCESS)
      fail(flag, "CVodeSetLinearSolver");
    if (jacobian && (flag = CVodeSetJacFn(c.memory, evaluate_jacobian)) != CV_SUCCESS)
      fail(flag, "CVodeSetJacFn");
    if ((flag = CVodeSetMaxOrd(c.memory, settings.maximum_order)) != CV_SUCCESS)
      fail(flag, "CVodeSetMaxOrd");
    if ((flag = CVodeSetStabLimDet(c.memory, settings.stability_limit_detection ? SUNTRUE : SUNFALSE)) != CV_SUCCESS)
      fail(flag, "CVodeSetStabLimDet");
  }

  TimeIntegrator::~TimeIntegrator() = default;

  void TimeIntegrator::fail(int flag, const char *call) const
  {
    if (cvode->error)
      {
        try
          {
            std::rethrow_exception(cvode->error);
          }
        catch (const std::exception &e)
          {
            throw std::runtime_error(context + ", t = " + format_number(t_now) + " s: " + e.what());
          }
      }
    throw std::runtime_error(context + ", t = " + format_number(t_now) + " s: the time integration failed (" + call +
                             ": " + CVodeGetReturnFlagName(flag) + (cvode->message.empty() ? "" : "; ") +
                             cvode->message + "); tighten `Dynamics/Relative tolerance' or raise `Dynamics/Maximum "
                                              "steps'");
  }

  void TimeIntegrator::start(double t0, const std::vector<double> &y0)
  {
    auto &c = *cvode;
    for (std::size_t k = 0; k < y0.size(); ++k)
      N_VGetArrayPointer(c.y)[k] = y0[k];
    t_now = t0;
    y_now = y0;
    c.error = nullptr;
    if (const int flag = CVodeReInit(c.memory, t0, c.y); flag != CV_SUCCESS)
      fail(flag, "CVodeReInit");
  }

  const std::vector<double> &TimeIntegrator::advance_to(double t)
  {
    long steps = 0;
    while (t_now < t)
      {
        step(t);
        count(++steps);
      }
    return y_now;
  }

  void TimeIntegrator::count(long steps) const
  {
    if (steps <= maximum_steps)
      return;
    // the component whose weighted local error estimate is largest is the one that holds the
    // step down: name what sets its speed
    std::string limited;
    const auto &c = *cvode;
    N_Vector weights = N_VClone(c.y), errors = N_VClone(c.y);
    if (CVodeGetErrWeights(c.memory, weights) == CV_SUCCESS && CVodeGetEstLocalErrors(c.memory, errors) == CV_SUCCESS)
      {
        std::size_t worst = 0;
        double largest = -1;
        for (sunindextype k = 0; k < N_VGetLength(c.y); ++k)
          if (const double e = std::abs(N_VGetArrayPointer(errors)[k] * N_VGetArrayPointer(weights)[k]); e > largest)
            largest = e, worst = std::size_t(k);
        limited = "; the steps are held down by " +
                  (describe_component ? describe_component(worst) : "component " + std::to_string(worst));
      }
    N_VDestroy(weights);
    N_VDestroy(errors);
    throw std::runtime_error(context + ", t = " + format_number(t_now) + " s: more than " + std::to_string(maximum_steps) +
                             " internal steps (CV_TOO_MUCH_WORK)" + limited +
                             ": the entries that make it fast, or `Dynamics/Maximum steps', are what to change");
  }

  double TimeIntegrator::step(double t_limit)
  {
    auto &c = *cvode;
    int flag = CVodeSetStopTime(c.memory, t_limit);
    if (flag != CV_SUCCESS)
      fail(flag, "CVodeSetStopTime");
    double t = t_now;
    flag = CVode(c.memory, t_limit, c.y, &t, CV_ONE_STEP);
    if (flag < 0)
      fail(flag, "CVode");
    c.error = nullptr; // a recovered trial step's error is no longer news
    t_now = t;
    const double *y = N_VGetArrayPointer(c.y);
    y_now.assign(y, y + y_now.size());
    return t_now;
  }

  double TimeIntegrator::integrate(double t_end, const std::function<bool(double, double)> &on_step)
  {
    long steps = 0;
    while (t_now < t_end)
      {
        const double t_previous = t_now;
        step(t_end);
        count(++steps);
        if (!on_step(t_previous, t_now))
          break;
      }
    return t_now;
  }

  std::vector<double> TimeIntegrator::interpolate(double t) const
  {
    auto &c = *cvode;
    N_Vector out = N_VClone(c.y);
    const int flag = CVodeGetDky(c.memory, t, 0, out);
    std::vector<double> y(N_VGetArrayPointer(out), N_VGetArrayPointer(out) + y_now.size());
    N_VDestroy(out);
    if (flag != CV_SUCCESS)
      fail(flag, "CVodeGetDky");
    return y;
  }

  TimeIntegrator::Statistics TimeIntegrator::statistics() const
  {
    Statistics s;
    long difference_quotient_evaluations = 0;
    void *m = cvode->memory;
    for (const auto &[flag, call] :
         {std::pair{CVodeGetNumSteps(m, &s.steps), "CVodeGetNumSteps"},
          std::pair{CVodeGetNumRhsEvals(m, &s.rhs_evaluations), "CVodeGetNumRhsEvals"},
          std::pair{CVodeGetNumJacEvals(m, &s.jacobian_evaluations), "CVodeGetNumJacEvals"},
          std::pair{CVodeGetNumErrTestFails(m, &s.error_test_failures), "CVodeGetNumErrTestFails"},
          std::pair{CVodeGetNumNonlinSolvIters(m, &s.nonlinear_iterations), "CVodeGetNumNonlinSolvIters"},
          std::pair{CVodeGetNumNonlinSolvConvFails(m, &s.convergence_failures), "CVodeGetNumNonlinSolvConvFails"},
          std::pair{CVodeGetLastOrder(m, &s.last_order), "CVodeGetLastOrder"},
          std::pair{CVodeGetNumLinRhsEvals(m, &difference_quotient_evaluations), "CVodeGetNumLinRhsEvals"}})
      if (flag != CV_SUCCESS)
        fail(flag, call);
    s.rhs_evaluations += difference_quotient_evaluations;
    return s;
  }
} // namespace servodrift::system
