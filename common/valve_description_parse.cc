// The valve description's values from a ParameterSource: the part of reading a valve description
// that needs no deal.II (the valve's core, the FMU).
#include "common/error.h"
#include "common/parameters/parameter_source.h"
#include "common/valve_description.h"

#include <fstream>
#include <sstream>

namespace servodrift
{
  void parse_valve_description(ParameterSource &source, ValveDescription &v)
  {
    v.operating.parse_parameters(source);
    v.torque_motor.parse_parameters(source);
    v.expansion.parse_parameters(source);
    v.spring_tube.parse_parameters(source);
    v.armature.parse_parameters(source);
    v.pilot.parse_parameters(source);
    v.spool.parse_parameters(source);
    v.fluid.parse_parameters(source);
    v.flow_solver.parse_parameters(source);
    v.offsets.parse_parameters(source);
    v.asymmetry.parse_parameters(source);
    v.sweeps.parse_parameters(source);
    v.dynamics.parse_parameters(source);
    v.tolerances.parse_parameters(source);
    v.fits.parse_parameters(source);
    v.output.parse_parameters(source);
  }

  ValveDescription read_printed_valve_description(const std::string &path)
  {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    if (!in || !(s << in.rdbuf()))
      throw InputError(path + ": cannot be read");
    PrmText text(s.str(), path);
    ValveDescription v;
    parse_valve_description(text, v);
    v.source = path;
    v.parameter_file = s.str();
    return v;
  }
} // namespace servodrift
