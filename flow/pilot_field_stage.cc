#include "flow/pilot_field_stage.h"

#include "common/csv.h"
#include "common/error.h"
#include "common/output_files.h"
#include "common/vtu_output.h"
#include "common/stage_output.h"
#include "common/sweep.h"
#include "common/units.h"
#include "common/version.h"
#include "flow/pilot_closed_forms.h"
#include "flow/pilot_field.h"

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace servodrift::flow
{
  namespace
  {
    using Turbulence = FlowSolverParameters::Turbulence;
    using FlowModel = PilotStageParameters::FlowModel;

    /// One computed case: the record every chain returns, from which the table and
    /// flow/field_cases.csv are built.
    enum Field : std::size_t
    {
      temperature,
      gap,
      pressure_difference,
      flow_rate,
      discharge_coefficient,
      reynolds_number,
      flapper_force,
      land_force,
      jet_force,
      bore_pressure,
      minimum_absolute_pressure,
      cavitating,
      max_wall_y_plus,
      max_turbulent_viscosity_ratio,
      iterations,
      model,
      flag,
      reduced_discharge_coefficient,
      reduced_flapper_force,
      wall_time,
      record_length
    };

    /// The field level was verified on RV-1's default sweep, where its discharge coefficients lie
    /// within a factor 1.31 of the reduced-order closed forms E21-E22 (the orifice cavitating at the
    /// full span 0.77 of E21, the nozzle at 10 um 1.29 of E22; doc/validation.md). Beyond this
    /// factor (a cold oil far below the sweep's Reynolds numbers, a geometry far from RV-1's) the
    /// case is flagged 4 and counted in the report (issue 24).
    constexpr double verified_discharge_factor = 1.35;

    bool beyond_verified(double field_discharge, double reduced_discharge)
    {
      return field_discharge > 0 && reduced_discharge > 0 &&
             std::abs(std::log(field_discharge / reduced_discharge)) > std::log(verified_discharge_factor);
    }

    double span(const ValveDescription &valve)
    {
      return valve.operating.supply_pressure - valve.operating.return_pressure;
    }

    std::vector<double> scaled(const std::vector<double> &fractions, double scale)
    {
      std::vector<double> v;
      for (double f : fractions)
        v.push_back(f * scale);
      return v;
    }

    const char *model_name(Turbulence t)
    {
      switch (t)
        {
          case Turbulence::laminar: return "laminar";
          case Turbulence::k_epsilon: return "k-epsilon";
          case Turbulence::k_epsilon_launder_sharma: return "k-epsilon-launder-sharma";
        }
      return "?";
    }

    /// The flow model of a case (D11): fixed, or laminar below the transition Reynolds number.
    Turbulence model_of_case(FlowModel m, double ideal_reynolds, double transition)
    {
      switch (m)
        {
          case FlowModel::laminar: return Turbulence::laminar;
          case FlowModel::k_epsilon: return Turbulence::k_epsilon;
          case FlowModel::k_epsilon_launder_sharma: return Turbulence::k_epsilon_launder_sharma;
          case FlowModel::automatic: break;
        }
      return ideal_reynolds < transition ? Turbulence::laminar : Turbulence::k_epsilon;
    }

    /// The table temperature whose cases go to VTU with `Output/Flow fields = reference'.
    double reference_table_temperature(const ValveDescription &valve)
    {
      double best = valve.sweeps.table_temperatures.front();
      for (double T : valve.sweeps.table_temperatures)
        if (std::abs(T - valve.operating.reference_temperature) < std::abs(best - valve.operating.reference_temperature))
          best = T;
      return best;
    }

    std::string flow_directory(const ValveDescription &valve) { return valve.output.directory + "/flow"; }

    std::string vtu_name(PilotGeometry g, double T, double h, double dp)
    {
      char name[96];
      if (g == PilotGeometry::fixed_orifice)
        std::snprintf(name, sizeof name, "fixed_orifice_T%.1f_dp%.3fMPa.vtu", T, dp * 1e-6);
      else
        std::snprintf(name, sizeof name, "nozzle_flapper_T%.1f_h%.2fum_dp%.3fMPa.vtu", T, h * 1e6, dp * 1e-6);
      return name;
    }

    bool writes_fields(const ValveDescription &valve, double T)
    {
      switch (valve.output.flow_fields)
        {
          case OutputParameters::FlowFields::all: return true;
          case OutputParameters::FlowFields::none: return false;
          case OutputParameters::FlowFields::reference: return T == reference_table_temperature(valve);
        }
      return false;
    }

    /// One continuation chain at a temperature: the cases of one geometry (and gap), created per
    /// flow model as needed, each new one starting from the last converged fields.
    class Chain
    {
    public:
      Chain(const ValveDescription &valve_, PilotGeometry g, double T)
        : valve(valve_)
        , kind(g)
        , conditions(pilot_field_case(valve_, T))
        , closed_forms(valve_, T)
      {}

      /// Solves the case of gap h (nozzle) at dp with the model the valve description asks for,
      /// from `start' if given (another gap's fields), else from the chain's last fields. Returns the
      /// record; keeps the fields if it converged.
      std::vector<double> solve(double h, double dp, const std::optional<FlowFields> &start = std::nullopt)
      {
        const auto begin = std::chrono::steady_clock::now();
        const auto &pilot = valve.pilot;
        const bool orifice = kind == PilotGeometry::fixed_orifice;
        if (!orifice && h != current_gap)
          cases.clear(), current_gap = h; // another mesh
        // the model: by the ideal-velocity Reynolds number of this case
        const double nu = conditions.fluid.viscosity / conditions.fluid.density;
        const auto g = closed_forms.geometry();
        const double length = orifice ? g.fixed_orifice_diameter : 2 * h;
        const double ideal_Re = length * std::sqrt(2 * dp / conditions.fluid.density) / nu;
        const Turbulence t = orifice ? model_of_case(pilot.fixed_orifice_flow_model, ideal_Re, pilot.fixed_orifice_transition_reynolds) :
                                       model_of_case(pilot.nozzle_flow_model, ideal_Re, pilot.nozzle_transition_reynolds);
        auto &slot = cases[t];
        if (!slot)
          {
            PilotFieldCase c = conditions;
            c.turbulence = t;
            slot = std::make_unique<PilotField>(valve, kind, c, h);
          }
        if (start)
          slot->set_fields(*start);
        else if (last && last_model != t)
          slot->set_fields(*last); // the chain switched model: continue from the other model's fields
        const std::string vtu = flow_directory(valve) + "/" + vtu_name(kind, conditions.temperature, h, dp);
        failure_output = writes_fields(valve, conditions.temperature) ? vtu : "";
        slot->set_failure_output(failure_output);

        std::vector<double> record(record_length, 0.0);
        record[temperature] = conditions.temperature;
        record[gap] = h;
        record[pressure_difference] = dp;
        record[model] = double(t);
        const OrificeState reduced = orifice ? closed_forms.fixed_orifice(dp) : closed_forms.nozzle(h, dp);
        record[reduced_discharge_coefficient] = reduced.discharge_coefficient;
        record[reduced_flapper_force] = reduced.flapper_force;
        try
          {
            const PilotFieldResult r = solve_with_retry(slot, t, h, dp, start.has_value());
            record[flow_rate] = r.flow_rate;
            record[discharge_coefficient] = r.discharge_coefficient;
            record[reynolds_number] = r.reynolds_number;
            record[flapper_force] = r.flapper_force;
            record[land_force] = r.land_force;
            record[jet_force] = r.jet_force;
            record[bore_pressure] = r.bore_pressure;
            record[minimum_absolute_pressure] = r.minimum_absolute_pressure;
            record[cavitating] = r.cavitating ? 1 : 0;
            record[max_wall_y_plus] = r.max_wall_y_plus;
            record[max_turbulent_viscosity_ratio] = r.max_turbulent_viscosity_ratio;
            record[iterations] = r.iterations;
            record[flag] = beyond_verified(record[discharge_coefficient], reduced.discharge_coefficient) ?
                             flags::beyond_verified :
                             flags::computed;
            last = slot->fields();
            last_model = t;
            last_dp = dp;
            if (writes_fields(valve, conditions.temperature))
              slot->write_vtu(vtu);
          }
        catch (const std::runtime_error &e) // NotConverged or diverged: flagged, the reduced order stands in
          {
            std::cerr << "servodrift: warning: " << (orifice ? "fixed orifice" : "nozzle-flapper") << " at "
                      << format_number(conditions.temperature) << " degC"
                      << (orifice ? "" : ", gap " + format_number(h * 1e6) + " um") << ", dp "
                      << format_number(dp * 1e-6) << " MPa (" << model_name(t) << "): " << e.what()
                      << "; its table row is flagged 2 and carries the reduced-order value\n";
            record[flow_rate] = reduced.flow_rate;
            record[discharge_coefficient] = reduced.discharge_coefficient;
            record[reynolds_number] = reduced.reynolds_number;
            record[flapper_force] = reduced.flapper_force;
            record[flag] = flags::not_converged;
            // the next case continues from the last converged fields, or starts up again
            if (last)
              slot->set_fields(*last);
            else
              slot.reset();
          }
        record[wall_time] = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
        return record;
      }

      const std::optional<FlowFields> &last_fields() const { return last; }

      /// The chain's last converged state: its fields, their flow model and pressure level.
      struct State
      {
        FlowFields fields;
        Turbulence model;
        double pressure_difference;
        template <class Archive>
        void serialize(Archive &archive, unsigned int)
        {
          archive &fields &model &pressure_difference;
        }
      };
      std::optional<State> state() const
      {
        return last ? std::optional<State>(State{*last, last_model, last_dp}) : std::nullopt;
      }
      /// Goes on from another chain's state as if this chain had converged to it (the next case
      /// continues from it, and a failing one is retried through the geometric mean of the levels).
      void resume(const State &s)
      {
        last = s.fields, last_model = s.model, last_dp = s.pressure_difference;
        PilotFieldCase c = conditions;
        c.turbulence = s.model;
        auto &slot = cases[s.model];
        slot = std::make_unique<PilotField>(valve, kind, c, current_gap > 0 ? current_gap : 0);
        slot->set_fields(s.fields);
      }

    private:
      /// Continuation step control: a case that does not converge from its starting fields is tried
      /// once more, from the chain's last converged fields of its own model through the geometric
      /// mean of the two pressure levels (half the step, in the logarithm), or, where there is no
      /// such state at this gap or it is the same pressure level, from rest (laminar start-up) with
      /// half the steps of `Field continuation ratio' (in the logarithm), so that the retry does not
      /// repeat the path that failed.
      /// The second failure propagates.
      PilotFieldResult solve_with_retry(std::unique_ptr<PilotField> &slot, Turbulence t, double h, double dp,
                                        bool started_elsewhere)
      {
        try
          {
            return slot->solve(dp);
          }
        catch (const std::runtime_error &)
          {
            const bool own_state = last && last_model == t && !started_elsewhere && last_dp != dp;
            PilotFieldCase c = conditions;
            c.turbulence = t;
            if (own_state)
              {
                slot->set_fields(*last);
                const double between = std::sqrt(last_dp * dp);
                PilotFieldResult r = slot->solve(between);
                const unsigned int iterations = r.iterations;
                r = slot->solve(dp);
                r.iterations += iterations;
                return r;
              }
            slot = std::make_unique<PilotField>(valve, kind, c, h);
            slot->set_failure_output(failure_output);
            // the smaller steps for this solve only: the chain's next cases take the valve's
            slot->set_continuation_ratio(std::sqrt(valve.pilot.field_continuation_ratio));
            try
              {
                PilotFieldResult r = slot->solve(dp);
                slot->set_continuation_ratio(valve.pilot.field_continuation_ratio);
                return r;
              }
            catch (const std::runtime_error &)
              {
                slot->set_continuation_ratio(valve.pilot.field_continuation_ratio);
                throw;
              }
          }
      }

      const ValveDescription &valve;
      PilotGeometry kind;
      PilotFieldCase conditions;
      PilotClosedForms closed_forms;
      double current_gap = -1;
      std::map<Turbulence, std::unique_ptr<PilotField>> cases;
      std::optional<FlowFields> last;
      Turbulence last_model = Turbulence::laminar;
      double last_dp = 0; ///< the pressure level of `last'
      std::string failure_output; ///< the VTU of the case being solved, if it fails
    };

  } // namespace
} // namespace servodrift::flow

namespace boost::serialization
{
  // the fields a chain continues from, for handing the orifice path's states between ranks
  template <class Archive>
  void serialize(Archive &archive, servodrift::flow::FlowFields &x, unsigned int)
  {
    static_assert(sizeof(x) == 280, "a member added to FlowFields must be serialised here");
    archive &x.u &x.v &x.p &x.flux &x.k &x.epsilon &x.turbulent_viscosity &x.face_area &x.density &x.boundary_pressures
      &x.turbulent &x.liquid_fraction &x.cavitating;
  }
} // namespace boost::serialization

namespace servodrift::flow
{
  namespace
  {
    /// The fixed orifice's first case (its lowest pressure difference) at every table temperature, as
    /// one continuation path: hottest first, each from the hotter temperature's converged fields (the
    /// same mesh topology, every dimension at its own temperature; `Sweeps/Table temperatures' is
    /// increasing). Only the hottest case starts from rest. Why: a start from rest is a laminar
    /// start-up and then k-epsilon seeded on laminar fields, 2 400-2 900 iterations at 1.03 MPa (RV-1),
    /// while a 10 degC step from converged fields takes 150-870 (doc/performance.md); and going down in
    /// temperature the path enters the laminar cases (lower Reynolds number) from turbulent fields,
    /// which they leave quickly. RV-1's 110 degC case stalls from rest and from 100 degC and converges
    /// from 120 degC. One rank computes it, as one case of the first sweep (run_chains).
    struct OrificeFirstCase
    {
      std::vector<double> record;
      std::optional<Chain::State> state; ///< empty if it did not converge
    };

    std::vector<OrificeFirstCase> orifice_first_cases(const ValveDescription &valve)
    {
      const auto &temperatures = valve.sweeps.table_temperatures;
      const double dp = valve.sweeps.field_orifice_pressure_fractions.front() * span(valve);
      std::vector<OrificeFirstCase> first(temperatures.size());
      std::optional<FlowFields> hotter; // the fields of the last temperature that converged
      for (std::size_t k = temperatures.size(); k-- > 0;)
        {
          Chain chain(valve, PilotGeometry::fixed_orifice, temperatures[k]);
          first[k].record = chain.solve(0, dp, hotter);
          first[k].state = chain.state();
          if (first[k].state)
            hotter = first[k].state->fields;
        }
      return first;
    }

    /// The path's states as bytes, for broadcast_bytes from the rank that computed them (boost
    /// serialization, as common/sweep's gathering of rows; the members of FlowFields and State below).
    std::vector<char> pack_states(const std::vector<OrificeFirstCase> &first)
    {
      std::vector<char> converged; // per temperature (a std::optional has no boost serialisation)
      std::vector<Chain::State> states;
      for (const auto &f : first)
        {
          converged.push_back(f.state.has_value());
          if (f.state)
            states.push_back(*f.state);
        }
      std::ostringstream out;
      boost::archive::binary_oarchive archive(out);
      archive << converged << states;
      const std::string bytes = out.str();
      return {bytes.begin(), bytes.end()};
    }

    std::vector<std::optional<Chain::State>> unpack_states(const std::vector<char> &bytes)
    {
      std::istringstream in(std::string(bytes.begin(), bytes.end()));
      boost::archive::binary_iarchive archive(in);
      std::vector<char> converged;
      std::vector<Chain::State> states;
      archive >> converged >> states;
      std::vector<std::optional<Chain::State>> out(converged.size());
      auto next = states.begin();
      for (std::size_t k = 0; k < converged.size(); ++k)
        if (converged[k])
          out[k] = std::move(*next++);
      return out;
    }

    /// The fixed orifice's other pressure differences at one temperature, in increasing order, from
    /// the first case's state (or from rest if it failed).
    CaseRows orifice_chain(const ValveDescription &valve, double T, const std::optional<Chain::State> &first)
    {
      Chain chain(valve, PilotGeometry::fixed_orifice, T);
      if (first)
        chain.resume(*first);
      CaseRows records;
      const auto dps = scaled(valve.sweeps.field_orifice_pressure_fractions, span(valve));
      for (std::size_t j = 1; j < dps.size(); ++j)
        records.push_back(chain.solve(0, dps[j]));
      return records;
    }

    /// The nozzle's gaps from the null gap outwards: x0, the smaller ones downwards, then the larger
    /// ones upwards, each with the index of the gap it starts from (-1: none).
    std::vector<std::pair<std::size_t, int>> gap_order(const std::vector<double> &fractions)
    {
      std::size_t middle = 0;
      for (std::size_t k = 0; k < fractions.size(); ++k)
        if (std::abs(fractions[k] - 1) < std::abs(fractions[middle] - 1))
          middle = k;
      std::vector<std::pair<std::size_t, int>> order{{middle, -1}};
      for (std::size_t k = middle; k-- > 0;)
        order.emplace_back(k, int(k + 1));
      for (std::size_t k = middle + 1; k < fractions.size(); ++k)
        order.emplace_back(k, int(k - 1));
      return order;
    }

    CaseRows nozzle_chain(const ValveDescription &valve, double T)
    {
      Chain chain(valve, PilotGeometry::nozzle_flapper, T);
      const auto gaps = scaled(valve.sweeps.field_gap_fractions, valve.pilot.null_gap);
      const auto dps = scaled(valve.sweeps.field_nozzle_pressure_fractions, span(valve));
      std::vector<std::optional<FlowFields>> first(gaps.size()); // each gap's fields at its first dp
      std::vector<CaseRows> by_gap(gaps.size());
      for (const auto &[k, from] : gap_order(valve.sweeps.field_gap_fractions))
        for (std::size_t j = 0; j < dps.size(); ++j)
          {
            by_gap[k].push_back(chain.solve(gaps[k], dps[j], j == 0 && from >= 0 ? first[from] : std::nullopt));
            if (j == 0)
              first[k] = chain.last_fields();
          }
      CaseRows records; // in gap order
      for (const auto &rows : by_gap)
        records.insert(records.end(), rows.begin(), rows.end());
      return records;
    }

    /// Reverses the order of the consecutive blocks of `block' rows (the chains of one geometry,
    /// which the sweep computes hottest first, back in increasing temperature).
    CaseRows blocks_reversed(const CaseRows &rows, std::size_t block)
    {
      CaseRows out;
      for (std::size_t end = rows.size(); end >= block && block > 0; end -= block)
        out.insert(out.end(), rows.begin() + std::ptrdiff_t(end - block), rows.begin() + std::ptrdiff_t(end));
      return out;
    }

    /// Two sweeps, each shared over the MPI ranks as one pool (`common/sweep': a free rank takes the
    /// next case): first the orifice's path over temperature (orifice_first_cases, one case, on one
    /// rank) beside the nozzle chains; then the orifice chains, each from its temperature's state on
    /// the path, which the rank that computed it hands to the others (broadcast_bytes). Each pool
    /// takes the hottest temperature first, since its lower viscosity and higher Reynolds numbers
    /// make its chains the longest (RV-1: 120 degC 61 s for the nozzle against 18 s at 40 degC).
    /// Why two sweeps: the orifice chains cannot start before the path has reached their
    /// temperature, and a sweep's cases are independent; with the path computed on every rank
    /// instead (so that one sweep held all 18 chains), each rank spent its 45 s (doc/performance.md).
    /// Returns the orifice's and the nozzle's records, each in increasing temperature.
    std::pair<CaseRows, CaseRows> run_chains(const ValveDescription &valve)
    {
      const auto &T = valve.sweeps.table_temperatures;
      const std::size_t n = T.size();
      on_rank_zero([&] { prepare_output_directory(flow_directory(valve)); });
      std::vector<OrificeFirstCase> first; // on the rank that computes the path
      const CaseRows path_and_nozzle = run_sweep(
        "flow: fixed orifice's path over temperature and nozzle-flapper chains (field)", n + 1,
        [&](std::size_t c) {
          if (c > 0)
            return nozzle_chain(valve, T[n - c]);
          first = orifice_first_cases(valve);
          CaseRows records;
          for (const auto &f : first)
            records.push_back(f.record);
          records.push_back({double(mpi_rank())}); // the rank that holds the path's states
          return records;
        },
        valve.output.progress);
      const unsigned int root = static_cast<unsigned int>(path_and_nozzle.at(n).at(0));
      std::vector<char> bytes;
      if (mpi_rank() == root)
        bytes = pack_states(first);
      const std::vector<std::optional<Chain::State>> states = unpack_states(broadcast_bytes(bytes, root));
      if (states.size() != n)
        throw std::logic_error("flow: the orifice path returned a wrong number of states");
      const CaseRows other_orifice_cases = run_sweep(
        "flow: fixed orifice chains (field)", n,
        [&](std::size_t c) {
          const std::size_t k = n - 1 - c; // the temperature's index, hottest first
          return orifice_chain(valve, T[k], states[k]);
        },
        valve.output.progress);

      const std::size_t orifice_block = valve.sweeps.field_orifice_pressure_fractions.size();
      if (other_orifice_cases.size() != n * (orifice_block - 1))
        throw std::logic_error("flow: a field chain returned a wrong number of cases");
      CaseRows orifice; // hottest first, each temperature's first case before its others
      for (std::size_t c = 0; c < n; ++c)
        {
          orifice.push_back(path_and_nozzle[n - 1 - c]);
          const auto others = other_orifice_cases.begin() + std::ptrdiff_t(c * (orifice_block - 1));
          orifice.insert(orifice.end(), others, others + std::ptrdiff_t(orifice_block - 1));
        }
      const CaseRows nozzle(path_and_nozzle.begin() + std::ptrdiff_t(n + 1), path_and_nozzle.end()); // hottest first
      const std::size_t nozzle_block =
        valve.sweeps.field_gap_fractions.size() * valve.sweeps.field_nozzle_pressure_fractions.size();
      if (orifice.size() != n * orifice_block || nozzle.size() != n * nozzle_block)
        throw std::logic_error("flow: a field chain returned a wrong number of cases");
      return {blocks_reversed(orifice, orifice_block), blocks_reversed(nozzle, nozzle_block)};
    }

    /// flow/<geometry>_cases.csv and the .pvd collection of the VTU files written (rank 0).
    void write_case_summary(const ValveDescription &valve, PilotGeometry g, const CaseRows &records)
    {
      const bool orifice = g == PilotGeometry::fixed_orifice;
      const std::string name = orifice ? "fixed_orifice" : "nozzle_flapper";
      on_rank_zero([&] {
        CsvDocument doc;
        doc.comments = {"servodrift-output " + name + "_cases",
                        "field-level " + std::string(orifice ? "fixed-orifice" : "nozzle-flapper") +
                          " cases: results, diagnostics (model.md 4.2, C12) and the reduced-order values (E21-E23) "
                          "beside them; flag 2 = not converged (the table carries the reduced-order value), 4 = "
                          "beyond the verified range (C_d and the reduced-order C_d differ by more than a factor " +
                          format_number(verified_discharge_factor) + ")",
                        "producer " + producer_string("flow/field"), "parameters-sha256 " + valve.parameters_sha256};
        doc.columns = {"temperature[degC]",
                       "gap[m]",
                       "pressure_difference[Pa]",
                       "flow_model[-]",
                       "flow_rate[m^3/s]",
                       "discharge_coefficient[1]",
                       "reduced_order_discharge_coefficient[1]",
                       "reynolds_number[1]",
                       "flapper_force[N]",
                       "reduced_order_flapper_force[N]",
                       "land_force[N]",
                       "jet_force[N]",
                       "bore_pressure[Pa]",
                       "minimum_absolute_pressure[Pa]",
                       "below_vapour_pressure[1]",
                       "max_wall_y_plus[1]",
                       "max_turbulent_viscosity_ratio[1]",
                       "iterations[1]",
                       "wall_time[s]",
                       "flag[1]"};
        std::vector<std::pair<double, std::string>> datasets;
        for (const auto &r : records)
          {
            const bool converged = r[flag] == flags::computed || r[flag] == flags::beyond_verified;
            auto cell = [&](double v, bool defined = true) { return defined ? format_cell(v) : std::string(); };
            doc.rows.push_back({cell(r[temperature]), cell(r[gap], !orifice), cell(r[pressure_difference]),
                                model_name(Turbulence(int(r[model]))), cell(r[flow_rate]), cell(r[discharge_coefficient]),
                                cell(r[reduced_discharge_coefficient]), cell(r[reynolds_number]),
                                cell(r[flapper_force], !orifice), cell(r[reduced_flapper_force], !orifice),
                                cell(r[land_force], !orifice && converged), cell(r[jet_force], !orifice && converged),
                                cell(r[bore_pressure], !orifice && converged), cell(r[minimum_absolute_pressure], converged),
                                cell(r[cavitating], converged), cell(r[max_wall_y_plus], converged),
                                cell(r[max_turbulent_viscosity_ratio], converged),
                                cell(r[iterations], converged), cell(r[wall_time]), cell(r[flag])});
            if (converged && writes_fields(valve, r[temperature]))
              datasets.emplace_back(datasets.size(), vtu_name(g, r[temperature], r[gap], r[pressure_difference]));
          }
        write_file_atomically(flow_directory(valve) + "/" + name + "_cases.csv", doc.text());
        if (!datasets.empty())
          write_pvd_atomically(flow_directory(valve) + "/" + name + ".pvd", datasets);
      });
    }

    std::size_t count_flagged(const CaseRows &records, std::size_t column, double value)
    {
      std::size_t n = 0;
      for (const auto &r : records)
        n += r[column] == value;
      return n;
    }

    void report_counts(const char *what, const CaseRows &records, bool valve_cavitation)
    {
      if (mpi_rank() != 0)
        return;
      const std::size_t failed = count_flagged(records, flag, flags::not_converged);
      const std::size_t cavitating_cases = count_flagged(records, cavitating, 1);
      if (failed > 0)
        std::cerr << "servodrift: warning: " << failed << " of " << records.size() << " " << what
                  << " cases did not converge (flag 2; see flow/*_cases.csv)\n";
      if (const std::size_t beyond = count_flagged(records, flag, flags::beyond_verified); beyond > 0)
        std::cerr << "servodrift: warning: " << beyond << " of " << records.size() << " " << what
                  << " cases lie beyond the range where the field level was verified: their C_d differs from the "
                     "reduced-order value by more than a factor "
                  << verified_discharge_factor << " (flag 4; see flow/*_cases.csv)\n";
      if (cavitating_cases > 0)
        std::cerr << "servodrift: note: " << cavitating_cases << " of " << records.size() << " " << what
                  << " cases cavitate ("
                  << (valve_cavitation ? "the equilibrium cavitation model holds those cells at the vapour pressure"
                                       : "Pilot stage/Field cavitation is off: the single-phase result stretches the "
                                         "liquid below its vapour pressure and is not physical there")
                  << "; model.md C12; flow/*_cases.csv)\n";
    }

    Table fixed_orifice_table(const ValveDescription &valve, const CaseRows &records)
    {
      Table table(schemas::fixed_orifice);
      std::size_t next = 0;
      for (double T : valve.sweeps.table_temperatures)
        {
          table.rows.push_back({T, 0.0, 0.0, 0.0, 0.0, flags::limit}); // no pressure difference, no flow
          for (std::size_t j = 0; j < valve.sweeps.field_orifice_pressure_fractions.size(); ++j, ++next)
            {
              const auto &r = records[next];
              table.rows.push_back({T, r[pressure_difference], r[flow_rate], r[discharge_coefficient], r[reynolds_number], r[flag]});
            }
        }
      return table;
    }

    Table nozzle_flapper_table(const ValveDescription &valve, const CaseRows &records)
    {
      Table table(schemas::nozzle_flapper);
      const auto gaps = scaled(valve.sweeps.field_gap_fractions, valve.pilot.null_gap);
      const auto dps = scaled(valve.sweeps.field_nozzle_pressure_fractions, span(valve));
      std::size_t next = 0;
      for (double T : valve.sweeps.table_temperatures)
        {
          const PilotClosedForms closed_forms(valve, T);
          // the closed gap: no flow, the control pressure on the bore's area (E23 at h = 0)
          table.rows.push_back({T, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, flags::limit});
          for (double dp : dps)
            table.rows.push_back({T, 0.0, dp, 0.0, 0.0, 0.0, closed_forms.nozzle(0.0, dp).flapper_force, flags::limit});
          for (double h : gaps)
            {
              table.rows.push_back({T, h, 0.0, 0.0, 0.0, 0.0, 0.0, flags::limit}); // no pressure difference
              for (std::size_t j = 0; j < dps.size(); ++j, ++next)
                {
                  const auto &r = records[next];
                  table.rows.push_back({T, h, r[pressure_difference], r[flow_rate], r[discharge_coefficient],
                                        r[reynolds_number], r[flapper_force], r[flag]});
                }
            }
        }
      return table;
    }
  } // namespace

  PilotTables compute_pilot_field_tables(const ValveDescription &valve)
  {
    const auto [orifice, nozzle] = run_chains(valve);
    write_case_summary(valve, PilotGeometry::fixed_orifice, orifice);
    write_case_summary(valve, PilotGeometry::nozzle_flapper, nozzle);
    report_counts("fixed-orifice", orifice, valve.pilot.field_cavitation);
    report_counts("nozzle-flapper", nozzle, valve.pilot.field_cavitation);
    return {fixed_orifice_table(valve, orifice), nozzle_flapper_table(valve, nozzle)};
  }
} // namespace servodrift::flow
