#pragma once
// Boost.Serialization of the dynamics' results (one member list per type), so that a case's result
// travels between MPI ranks through run_sweep bit for bit (common/sweep_objects.h). Include it only
// where the results are packed and unpacked (dynamics.cc).
#include "system/dynamics.h"

#include <boost/serialization/array.hpp>
#include <boost/serialization/complex.hpp>
#include <boost/serialization/split_free.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

namespace boost::serialization
{
  // std::optional (Boost 1.74 knows only boost::optional)
  template <class Archive, class T>
  void save(Archive &a, const std::optional<T> &o, unsigned int)
  {
    const bool present = o.has_value();
    a << present;
    if (present)
      a << *o;
  }

  template <class Archive, class T>
  void load(Archive &a, std::optional<T> &o, unsigned int)
  {
    bool present = false;
    a >> present;
    o.reset();
    if (present)
      {
        T value;
        a >> value;
        o = value;
      }
  }

  template <class Archive, class T>
  void serialize(Archive &a, std::optional<T> &o, unsigned int version)
  {
    split_free(a, o, version);
  }

  template <class Archive>
  void serialize(Archive &a, servodrift::system::ValveState &s, unsigned int)
  {
    for (auto member : servodrift::system::state_members)
      a &(s.*member);
  }

  template <class Archive>
  void serialize(Archive &a, servodrift::system::Mode &m, unsigned int)
  {
    a &m.eigenvalue &m.name &m.natural_frequency &m.damping_ratio &m.participation;
  }

  template <class Archive>
  void serialize(Archive &a, servodrift::system::FrequencyResponse &r, unsigned int)
  {
    a &r.output &r.dc_gain &r.frequencies &r.values &r.amplitude_db &r.phase_degrees &r.bandwidth &r.phase_90_frequency;
  }

  template <class Archive>
  void serialize(Archive &a, servodrift::system::DynamicChecks &c, unsigned int)
  {
    a &c.armature_closed_form &c.armature_blocked &c.armature_compressible &c.armature_coupled &
      c.pressure_time_constant_closed_form &c.pressure_time_constant_tables &c.pressure_time_constant;
  }

  template <class Archive>
  void serialize(Archive &a, servodrift::system::SteadyStateCheck &c, unsigned int)
  {
    a &c.drift_from_static &c.distance_from_rest &c.settling_from_rest &c.duration;
  }

  template <class Archive>
  void serialize(Archive &a, servodrift::system::StepMetrics &m, unsigned int)
  {
    a &m.initial &m.final &m.rise_time &m.overshoot &m.settling_time;
  }

  template <class Archive>
  void serialize(Archive &a, servodrift::system::TimeIntegrator::Statistics &s, unsigned int)
  {
    a &s.steps &s.rhs_evaluations &s.jacobian_evaluations &s.error_test_failures &s.nonlinear_iterations &
      s.convergence_failures &s.last_order;
  }

  template <class Archive>
  void serialize(Archive &a, servodrift::system::StepResponse &r, unsigned int)
  {
    a &r.from_current &r.to_current &r.duration &r.times &r.states &r.metrics &r.final_distance &r.flapper_contact &
      r.spool_on_stop &r.left_tables &r.statistics;
  }

  template <class Archive>
  void serialize(Archive &a, servodrift::system::ColdStart &c, unsigned int)
  {
    a &c.temperature &c.response;
  }

  template <class Archive>
  void serialize(Archive &a, servodrift::system::SineResponse &r, unsigned int)
  {
    a &r.frequency &r.amplitude &r.periods &r.periodic &r.response_periods &r.shooting_steps &r.last_change &r.gain &
      r.minimum &r.maximum &r.distortion &r.subharmonic &r.flapper_contact &r.beyond_lap &r.spool_on_stop &
      r.left_tables &r.failure;
  }

  template <class Archive>
  void serialize(Archive &a, servodrift::system::SineCheck &c, unsigned int)
  {
    a &c.frequency &c.linear &c.dc_gain &c.halvings &c.linear_limit;
  }

  template <class Archive>
  void serialize(Archive &a, servodrift::system::TemperatureDynamics &d, unsigned int)
  {
    a &d.temperature &d.bias &d.bias_point &d.hydraulic_null &d.bias_spool_state &d.modes &d.brake_pressure &d.spool_displacement &
      d.checks &d.steady &d.large_step &d.small_step &d.sine_checks &d.sine_study &d.sine_study_down;
  }
} // namespace boost::serialization
