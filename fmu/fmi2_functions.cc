// The FMI 2.0 C functions of the valve FMU (Model Exchange and Co-Simulation in one binary): each
// turns its arguments into a call of ValveFmu and every exception into a logged message and
// fmi2Error, so that nothing a host or a resource file does can crash the host. No global state:
// everything lives in the instance.
#include "common/error.h"
#include "fmu/fmi2.h"
#include "fmu/valve_fmu.h"

#include <cstring>
#include <exception>
#include <fstream>
#include <memory>
#include <string>

#define FMI2_EXPORT extern "C" __attribute__((visibility("default")))

namespace
{
  using servodrift::fmu::ValveFmu;

  struct Instance
  {
    std::string name;
    fmi2Type type;
    fmi2CallbackLogger logger = nullptr;
    fmi2ComponentEnvironment environment = nullptr;
    bool debug_logging = false;
    bool warned = false; ///< a warning was logged during the current call
    std::unique_ptr<ValveFmu> fmu;

    void log(fmi2Status status, const char *category, const std::string &message)
    {
      if (!logger)
        return;
      std::string text; // `#' starts a value reference in FMI messages: `##' is a `#'
      for (char ch : message)
        text += ch == '#' ? std::string("##") : std::string(1, ch);
      logger(environment, name.c_str(), status, category, "%s", text.c_str());
    }
  };

  /// Runs `f' on the instance; an exception becomes a logged error, a warning logged meanwhile fmi2Warning.
  template <typename F> fmi2Status guarded(fmi2Component c, const char *function, F &&f)
  {
    auto *i = static_cast<Instance *>(c);
    if (!i)
      return fmi2Error;
    i->warned = false;
    try
      {
        f(*i);
        return i->warned ? fmi2Warning : fmi2OK;
      }
    catch (const std::exception &e)
      {
        i->log(fmi2Error, "logStatusError", std::string(function) + ": " + e.what());
      }
    catch (...)
      {
        i->log(fmi2Error, "logStatusError", std::string(function) + ": an unknown error");
      }
    return fmi2Error;
  }

  /// The directory of a resource location: a file URI (file:///dir, file:/dir, file://localhost/dir,
  /// with %XX escapes) or a plain path
  std::string directory_of(const std::string &uri)
  {
    std::string path = uri;
    if (path.rfind("file://localhost/", 0) == 0)
      path = path.substr(16);
    else if (path.rfind("file:///", 0) == 0)
      path = path.substr(7);
    else if (path.rfind("file:/", 0) == 0)
      path = path.substr(5);
    std::string decoded;
    for (std::size_t k = 0; k < path.size(); ++k)
      if (path[k] == '%' && k + 2 < path.size())
        {
          decoded += static_cast<char>(std::stoi(path.substr(k + 1, 2), nullptr, 16));
          k += 2;
        }
      else
        decoded += path[k];
    while (decoded.size() > 1 && decoded.back() == '/')
      decoded.pop_back();
    return decoded;
  }

  std::string guid_of(const std::string &resources)
  {
    std::ifstream in(resources + "/provenance.txt");
    if (!in)
      throw servodrift::InputError(resources + "/provenance.txt: cannot be read (is the resource location the "
                                               "FMU's resources/ directory?)");
    for (std::string line; std::getline(in, line);)
      if (line.rfind("guid ", 0) == 0)
        return line.substr(5);
    return "";
  }

  fmi2Status no_variables(fmi2Component c, const char *function, std::size_t nvr)
  {
    return guarded(c, function, [&](Instance &) {
      if (nvr > 0)
        throw servodrift::InputError("the FMU has no variables of this type");
    });
  }
} // namespace

FMI2_EXPORT const char *fmi2GetTypesPlatform()
{
  return "default";
}
FMI2_EXPORT const char *fmi2GetVersion()
{
  return "2.0";
}

FMI2_EXPORT fmi2Component fmi2Instantiate(fmi2String instance_name, fmi2Type type, fmi2String guid,
                                          fmi2String resource_location, const fmi2CallbackFunctions *functions,
                                          fmi2Boolean, fmi2Boolean logging_on)
{
  auto instance = std::make_unique<Instance>();
  instance->name = instance_name ? instance_name : "";
  instance->type = type;
  if (functions)
    {
      instance->logger = functions->logger;
      instance->environment = functions->componentEnvironment;
    }
  instance->debug_logging = logging_on;
  const fmi2Status status = guarded(instance.get(), "fmi2Instantiate", [&](Instance &i) {
    if (type != fmi2ModelExchange && type != fmi2CoSimulation)
      throw servodrift::InputError("unknown FMU type " + std::to_string(type));
    if (!resource_location || !*resource_location)
      throw servodrift::InputError("no resource location");
    const std::string resources = directory_of(resource_location);
    const std::string expected = guid_of(resources);
    if (!guid || expected != guid)
      throw servodrift::InputError("the GUID " + std::string(guid ? guid : "(none)") + " is not this FMU's (" +
                                   resources + "/provenance.txt says " + expected + ")");
    i.fmu =
        std::make_unique<ValveFmu>(resources, type == fmi2CoSimulation, [&i](bool warning, const std::string &message) {
          if (warning)
            i.warned = true;
          if (warning || i.debug_logging)
            i.log(warning ? fmi2Warning : fmi2OK, warning ? "logStatusWarning" : "logInfo", message);
        });
  });
  if (status == fmi2Error)
    return nullptr;
  return instance.release();
}

FMI2_EXPORT void fmi2FreeInstance(fmi2Component c)
{
  delete static_cast<Instance *>(c);
}

FMI2_EXPORT fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean logging_on, std::size_t, const fmi2String[])
{
  return guarded(c, "fmi2SetDebugLogging", [&](Instance &i) { i.debug_logging = logging_on; });
}

FMI2_EXPORT fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean tolerance_defined, fmi2Real tolerance,
                                           fmi2Real start_time, fmi2Boolean, fmi2Real)
{
  return guarded(c, "fmi2SetupExperiment",
                 [&](Instance &i) { i.fmu->setup_experiment(start_time, tolerance_defined ? tolerance : 0); });
}

FMI2_EXPORT fmi2Status fmi2EnterInitializationMode(fmi2Component c)
{
  return guarded(c, "fmi2EnterInitializationMode", [](Instance &) {});
}

FMI2_EXPORT fmi2Status fmi2ExitInitializationMode(fmi2Component c)
{
  return guarded(c, "fmi2ExitInitializationMode", [](Instance &i) { i.fmu->exit_initialization(); });
}

FMI2_EXPORT fmi2Status fmi2Terminate(fmi2Component c)
{
  return guarded(c, "fmi2Terminate", [](Instance &) {});
}

FMI2_EXPORT fmi2Status fmi2Reset(fmi2Component c)
{
  return guarded(c, "fmi2Reset", [](Instance &i) { i.fmu->reset(); });
}

FMI2_EXPORT fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], std::size_t n, fmi2Real value[])
{
  return guarded(c, "fmi2GetReal", [&](Instance &i) {
    for (std::size_t k = 0; k < n; ++k)
      value[k] = i.fmu->get_real(vr[k]);
  });
}

FMI2_EXPORT fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], std::size_t n,
                                   const fmi2Real value[])
{
  return guarded(c, "fmi2SetReal", [&](Instance &i) {
    for (std::size_t k = 0; k < n; ++k)
      i.fmu->set_real(vr[k], value[k]);
  });
}

FMI2_EXPORT fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], std::size_t n,
                                      fmi2Boolean value[])
{
  return guarded(c, "fmi2GetBoolean", [&](Instance &i) {
    for (std::size_t k = 0; k < n; ++k)
      value[k] = i.fmu->get_boolean(vr[k]) ? fmi2True : fmi2False;
  });
}

FMI2_EXPORT fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], std::size_t n,
                                      const fmi2Boolean value[])
{
  return guarded(c, "fmi2SetBoolean", [&](Instance &i) {
    for (std::size_t k = 0; k < n; ++k)
      i.fmu->set_boolean(vr[k], value[k] != fmi2False);
  });
}

FMI2_EXPORT fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference[], std::size_t n, fmi2Integer[])
{
  return no_variables(c, "fmi2GetInteger", n);
}
FMI2_EXPORT fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference[], std::size_t n, const fmi2Integer[])
{
  return no_variables(c, "fmi2SetInteger", n);
}
FMI2_EXPORT fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference[], std::size_t n, fmi2String[])
{
  return no_variables(c, "fmi2GetString", n);
}
FMI2_EXPORT fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference[], std::size_t n, const fmi2String[])
{
  return no_variables(c, "fmi2SetString", n);
}

// --- the FMU state: a snapshot of time, states and inputs (the integrator restarts from it)
FMI2_EXPORT fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *state)
{
  return guarded(c, "fmi2GetFMUstate", [&](Instance &i) {
    auto *s = static_cast<servodrift::fmu::Snapshot *>(*state);
    if (s)
      *s = i.fmu->save();
    else
      *state = new servodrift::fmu::Snapshot(i.fmu->save());
  });
}

FMI2_EXPORT fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate state)
{
  return guarded(c, "fmi2SetFMUstate", [&](Instance &i) {
    if (!state)
      throw servodrift::InputError("no FMU state");
    i.fmu->restore(*static_cast<servodrift::fmu::Snapshot *>(state));
  });
}

FMI2_EXPORT fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *state)
{
  return guarded(c, "fmi2FreeFMUstate", [&](Instance &) {
    delete static_cast<servodrift::fmu::Snapshot *>(*state);
    *state = nullptr;
  });
}

FMI2_EXPORT fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate state, std::size_t *size)
{
  return guarded(c, "fmi2SerializedFMUstateSize", [&](Instance &) {
    *size = servodrift::fmu::serialized_size(*static_cast<servodrift::fmu::Snapshot *>(state));
  });
}

FMI2_EXPORT fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate state, fmi2Byte bytes[], std::size_t size)
{
  return guarded(c, "fmi2SerializeFMUstate", [&](Instance &) {
    servodrift::fmu::serialize(*static_cast<servodrift::fmu::Snapshot *>(state), bytes, size);
  });
}

FMI2_EXPORT fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte bytes[], std::size_t size,
                                               fmi2FMUstate *state)
{
  return guarded(c, "fmi2DeSerializeFMUstate", [&](Instance &) {
    auto s = std::make_unique<servodrift::fmu::Snapshot>(servodrift::fmu::deserialize(bytes, size));
    delete static_cast<servodrift::fmu::Snapshot *>(*state);
    *state = s.release();
  });
}

FMI2_EXPORT fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference[], std::size_t,
                                                    const fmi2ValueReference[], std::size_t, const fmi2Real[],
                                                    fmi2Real[])
{
  return guarded(c, "fmi2GetDirectionalDerivative", [](Instance &) {
    throw servodrift::InputError("not provided (providesDirectionalDerivative is false)");
  });
}

// --- Model Exchange
FMI2_EXPORT fmi2Status fmi2EnterEventMode(fmi2Component c)
{
  return guarded(c, "fmi2EnterEventMode", [](Instance &) {});
}

FMI2_EXPORT fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo *info)
{
  return guarded(c, "fmi2NewDiscreteStates", [&](Instance &) {
    // event-free: the contacts and stops are smooth laws of the states (model.md 1.20)
    info->newDiscreteStatesNeeded = fmi2False;
    info->terminateSimulation = fmi2False;
    info->nominalsOfContinuousStatesChanged = fmi2False;
    info->valuesOfContinuousStatesChanged = fmi2False;
    info->nextEventTimeDefined = fmi2False;
    info->nextEventTime = 0;
  });
}

FMI2_EXPORT fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c)
{
  return guarded(c, "fmi2EnterContinuousTimeMode", [](Instance &) {});
}

FMI2_EXPORT fmi2Status fmi2CompletedIntegratorStep(fmi2Component c, fmi2Boolean, fmi2Boolean *enter_event_mode,
                                                   fmi2Boolean *terminate)
{
  return guarded(c, "fmi2CompletedIntegratorStep", [&](Instance &) {
    *enter_event_mode = fmi2False;
    *terminate = fmi2False;
  });
}

FMI2_EXPORT fmi2Status fmi2SetTime(fmi2Component c, fmi2Real time)
{
  return guarded(c, "fmi2SetTime", [&](Instance &i) { i.fmu->set_time(time); });
}

FMI2_EXPORT fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], std::size_t n)
{
  return guarded(c, "fmi2SetContinuousStates", [&](Instance &i) { i.fmu->set_states(x, n); });
}

FMI2_EXPORT fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], std::size_t n)
{
  return guarded(c, "fmi2GetContinuousStates", [&](Instance &i) { i.fmu->get_states(x, n); });
}

FMI2_EXPORT fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real dx[], std::size_t n)
{
  return guarded(c, "fmi2GetDerivatives", [&](Instance &i) { i.fmu->derivatives(dx, n); });
}

FMI2_EXPORT fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real[], std::size_t n)
{
  return guarded(c, "fmi2GetEventIndicators", [&](Instance &) {
    if (n > 0)
      throw servodrift::InputError("the FMU has no event indicators");
  });
}

FMI2_EXPORT fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x[], std::size_t n)
{
  return guarded(c, "fmi2GetNominalsOfContinuousStates", [&](Instance &i) { i.fmu->nominals(x, n); });
}

// --- Co-Simulation
FMI2_EXPORT fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference[], std::size_t,
                                                   const fmi2Integer[], const fmi2Real[])
{
  return guarded(c, "fmi2SetRealInputDerivatives", [](Instance &) {
    throw servodrift::InputError("not provided (canInterpolateInputs is false: inputs are held over a step)");
  });
}

FMI2_EXPORT fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference[], std::size_t,
                                                    const fmi2Integer[], fmi2Real[])
{
  return guarded(c, "fmi2GetRealOutputDerivatives",
                 [](Instance &) { throw servodrift::InputError("not provided (maxOutputDerivativeOrder is 0)"); });
}

FMI2_EXPORT fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean)
{
  return guarded(c, "fmi2DoStep", [&](Instance &i) { i.fmu->do_step(t, h); });
}

FMI2_EXPORT fmi2Status fmi2CancelStep(fmi2Component c)
{
  return guarded(c, "fmi2CancelStep", [](Instance &) {
    throw servodrift::InputError("fmi2DoStep never returns fmi2Pending: nothing to cancel");
  });
}

FMI2_EXPORT fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind, fmi2Status *value)
{
  return guarded(c, "fmi2GetStatus", [&](Instance &) { *value = fmi2OK; });
}

FMI2_EXPORT fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind kind, fmi2Real *value)
{
  return guarded(c, "fmi2GetRealStatus", [&](Instance &i) {
    if (kind != fmi2LastSuccessfulTime)
      throw servodrift::InputError("only fmi2LastSuccessfulTime is a Real status");
    *value = i.fmu->time();
  });
}

FMI2_EXPORT fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind, fmi2Integer *)
{
  return guarded(c, "fmi2GetIntegerStatus", [](Instance &) { throw servodrift::InputError("no Integer status"); });
}

FMI2_EXPORT fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind kind, fmi2Boolean *value)
{
  return guarded(c, "fmi2GetBooleanStatus", [&](Instance &) {
    if (kind != fmi2Terminated)
      throw servodrift::InputError("only fmi2Terminated is a Boolean status");
    *value = fmi2False;
  });
}

FMI2_EXPORT fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind, fmi2String *)
{
  return guarded(c, "fmi2GetStringStatus", [](Instance &) { throw servodrift::InputError("no String status"); });
}
