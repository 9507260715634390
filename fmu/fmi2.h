#pragma once
// The C interface of FMI 2.0 (Functional Mock-up Interface for Model Exchange and Co-Simulation,
// version 2.0, Modelica Association), declared from the standard's text: its types (2.1.2), the
// common functions (2.1.4-2.1.9), those of Model Exchange (3.2) and of Co-Simulation (4.2). Only
// what the valve's FMU defines; the default platform ("default": double, int, char).
#include <cstddef>

extern "C"
{
  typedef void *fmi2Component;
  typedef void *fmi2ComponentEnvironment;
  typedef void *fmi2FMUstate;
  typedef unsigned int fmi2ValueReference;
  typedef double fmi2Real;
  typedef int fmi2Integer;
  typedef int fmi2Boolean;
  typedef char fmi2Char;
  typedef const fmi2Char *fmi2String;
  typedef char fmi2Byte;

  enum
  {
    fmi2False = 0,
    fmi2True = 1
  };

  typedef enum
  {
    fmi2OK,
    fmi2Warning,
    fmi2Discard,
    fmi2Error,
    fmi2Fatal,
    fmi2Pending
  } fmi2Status;

  typedef enum
  {
    fmi2ModelExchange,
    fmi2CoSimulation
  } fmi2Type;

  typedef enum
  {
    fmi2DoStepStatus,
    fmi2PendingStatus,
    fmi2LastSuccessfulTime,
    fmi2Terminated
  } fmi2StatusKind;

  typedef void (*fmi2CallbackLogger)(fmi2ComponentEnvironment, fmi2String instance_name, fmi2Status status,
                                     fmi2String category, fmi2String message, ...);
  typedef void *(*fmi2CallbackAllocateMemory)(std::size_t count, std::size_t size);
  typedef void (*fmi2CallbackFreeMemory)(void *);
  typedef void (*fmi2StepFinished)(fmi2ComponentEnvironment, fmi2Status);

  typedef struct
  {
    const fmi2CallbackLogger logger;
    const fmi2CallbackAllocateMemory allocateMemory;
    const fmi2CallbackFreeMemory freeMemory;
    const fmi2StepFinished stepFinished;
    const fmi2ComponentEnvironment componentEnvironment;
  } fmi2CallbackFunctions;

  typedef struct
  {
    fmi2Boolean newDiscreteStatesNeeded;
    fmi2Boolean terminateSimulation;
    fmi2Boolean nominalsOfContinuousStatesChanged;
    fmi2Boolean valuesOfContinuousStatesChanged;
    fmi2Boolean nextEventTimeDefined;
    fmi2Real nextEventTime;
  } fmi2EventInfo;
}
