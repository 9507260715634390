// The valve FMU's speeds (issue 64), through its C interface as a host calls it (dlopen):
//   instantiation (reading resources/): target at most 50 ms;
//   one derivative evaluation (Model Exchange): target at most 20 us, at fixed inputs and with the
//     oil temperature moving at every call (the equations rebuilt);
//   Co-Simulation, 1 s of valve time after a step to the rated current in 1 ms communication steps:
//     target at most 0.5 s of one core.
// Usage: unzip -q -o <out>/servodrift_valve.fmu -d <dir> && build/bench/bench_fmu <dir>
#include "bench/figures.h"
#include "bench/time_it.h"
#include "fmu/fmi2.h"

#include <dlfcn.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
  void logger(fmi2ComponentEnvironment, fmi2String, fmi2Status status, fmi2String, fmi2String, ...)
  {
    if (status >= fmi2Warning)
      std::fprintf(stderr, "bench_fmu: the FMU logged a status %d\n", status);
  }

  template <typename F> F symbol(void *library, const char *name)
  {
    void *s = dlsym(library, name);
    if (!s)
      throw std::runtime_error(std::string("no ") + name + " in the FMU's binary");
    return reinterpret_cast<F>(s);
  }
} // namespace

int main(int argc, char **argv)
{
  if (argc != 2)
    {
      std::fprintf(stderr, "usage: bench_fmu <unpacked FMU directory>\n");
      return 2;
    }
  const std::string dir = argv[1];
  void *library = dlopen((dir + "/binaries/linux64/servodrift_valve.so").c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!library)
    {
      std::fprintf(stderr, "bench_fmu: %s\n", dlerror());
      return 1;
    }
  // the GUID and value references from modelDescription.xml
  std::ifstream xml_file(dir + "/modelDescription.xml");
  std::stringstream xml;
  xml << xml_file.rdbuf();
  const std::string text = xml.str();
  std::smatch m;
  std::regex_search(text, m, std::regex("guid=\"([^\"]+)\""));
  const std::string guid = m[1];
  std::map<std::string, fmi2ValueReference> vr;
  const std::regex variable("name=\"([^\"]+)\" valueReference=\"([0-9]+)\"");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), variable); it != std::sregex_iterator(); ++it)
    vr[(*it)[1]] = static_cast<fmi2ValueReference>(std::stoul((*it)[2]));
  std::size_t n = 0;
  for (const auto &[name, r] : vr)
    n += name.rfind("der(", 0) == 0;

  using Instantiate = fmi2Component (*)(fmi2String, fmi2Type, fmi2String, fmi2String, const fmi2CallbackFunctions *,
                                        fmi2Boolean, fmi2Boolean);
  const auto instantiate = symbol<Instantiate>(library, "fmi2Instantiate");
  const auto free_instance = symbol<void (*)(fmi2Component)>(library, "fmi2FreeInstance");
  const auto set_real =
      symbol<fmi2Status (*)(fmi2Component, const fmi2ValueReference *, std::size_t, const fmi2Real *)>(library,
                                                                                                       "fmi2SetReal");
  const auto enter = symbol<fmi2Status (*)(fmi2Component)>(library, "fmi2EnterInitializationMode");
  const auto exit = symbol<fmi2Status (*)(fmi2Component)>(library, "fmi2ExitInitializationMode");
  const auto set_states =
      symbol<fmi2Status (*)(fmi2Component, const fmi2Real *, std::size_t)>(library, "fmi2SetContinuousStates");
  const auto get_states =
      symbol<fmi2Status (*)(fmi2Component, fmi2Real *, std::size_t)>(library, "fmi2GetContinuousStates");
  const auto derivatives =
      symbol<fmi2Status (*)(fmi2Component, fmi2Real *, std::size_t)>(library, "fmi2GetDerivatives");
  const auto do_step = symbol<fmi2Status (*)(fmi2Component, fmi2Real, fmi2Real, fmi2Boolean)>(library, "fmi2DoStep");

  const fmi2CallbackFunctions callbacks = {logger, std::calloc, std::free, nullptr, nullptr};
  const std::string resources = "file://" + dir + "/resources";
  const auto started = [&](fmi2Type type) {
    fmi2Component c = instantiate("bench", type, guid.c_str(), resources.c_str(), &callbacks, fmi2False, fmi2False);
    if (!c || enter(c) != fmi2OK || exit(c) != fmi2OK)
      throw std::runtime_error("the FMU did not start");
    return c;
  };
  const fmi2ValueReference current = vr.at("coil_current"), temperature = vr.at("oil_temperature");
  const double rated = 0.02, T0 = 313.15;

  const auto [instantiate_min, instantiate_median] = servodrift::bench::time_it(20, [&] {
    free_instance(
        instantiate("bench", fmi2ModelExchange, guid.c_str(), resources.c_str(), &callbacks, fmi2False, fmi2False));
  });
  std::printf("instantiation (reading resources/): min %.2f ms, median %.2f ms (target <= 50 ms)\n",
              1e3 * instantiate_min, 1e3 * instantiate_median);

  fmi2Component me = started(fmi2ModelExchange);
  std::vector<double> x(n), dx(n);
  get_states(me, x.data(), n);
  set_real(me, &current, 1, &rated);
  const int calls = 100000;
  const auto [fixed_min, fixed_median] = servodrift::bench::time_it(5, [&] {
    for (int k = 0; k < calls; ++k)
      {
        set_states(me, x.data(), n);
        derivatives(me, dx.data(), n);
      }
  });
  const auto [moving_min, moving_median] = servodrift::bench::time_it(5, [&] {
    for (int k = 0; k < calls; ++k)
      {
        const double T = T0 + 1e-4 * (k % 1000); // within the tables' range, a new value at each call
        set_real(me, &temperature, 1, &T);
        set_states(me, x.data(), n);
        derivatives(me, dx.data(), n);
      }
  });
  std::printf("one derivative evaluation (fmi2SetContinuousStates + fmi2GetDerivatives): min %.2f us, median "
              "%.2f us at fixed inputs; min %.2f us, median %.2f us with the temperature moving (target <= 20 us)\n",
              1e6 * fixed_min / calls, 1e6 * fixed_median / calls, 1e6 * moving_min / calls,
              1e6 * moving_median / calls);
  free_instance(me);

  const auto [cs_min, cs_median] = servodrift::bench::time_it(5, [&] {
    fmi2Component cs = started(fmi2CoSimulation);
    set_real(cs, &current, 1, &rated);
    for (int k = 0; k < 1000; ++k)
      if (do_step(cs, 1e-3 * k, 1e-3, fmi2True) != fmi2OK)
        throw std::runtime_error("fmi2DoStep failed");
    free_instance(cs);
  });
  std::printf("Co-Simulation, 1 s of valve time in 1 ms steps after a step to the rated current: min %.3f s, "
              "median %.3f s (target <= 0.5 s)\n",
              cs_min, cs_median);
  const servodrift::bench::Figures figures(argc, argv);
  figures.record("FMU instantiation (reading resources/)", "at most 50 ms", servodrift::bench::seconds(instantiate_median));
  figures.record("FMU, one derivative evaluation (Model Exchange), the temperature moving", "at most 20 us",
                 servodrift::bench::seconds(moving_median / calls));
  figures.record("FMU Co-Simulation, 1 s of valve time in 1 ms steps", "at most 0.5 s of one core",
                 servodrift::bench::seconds(cs_median));
  dlclose(library);
  return 0;
}
