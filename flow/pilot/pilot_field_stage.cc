#include "flow/pilot/pilot_field_stage.h"

#include "common/output_files.h"
#include "common/stage_output.h"
#include "common/sweep.h"
#include "flow/pilot/pilot_field_cases.h"

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>

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
  using namespace case_record;

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
      /// the nearest hotter states on the path of the other flow models, for the temperature's
      /// chain to switch to (Chain::offer; RV-1: the laminar 40 and 50 degC get 60 degC's k-epsilon)
      std::vector<Chain::State> other_models;
    };

    std::vector<OrificeFirstCase> orifice_first_cases(const ValveDescription &valve)
    {
      const auto &temperatures = valve.sweeps.table_temperatures;
      const double dp = valve.sweeps.field_orifice_pressure_fractions.front() * span(valve);
      std::vector<OrificeFirstCase> first(temperatures.size());
      std::optional<FlowFields> hotter; // the fields of the last temperature that converged
      std::map<Turbulence, Chain::State> hotter_of_model; // the same, per flow model
      for (std::size_t k = temperatures.size(); k-- > 0;)
        {
          Chain chain(valve, PilotGeometry::fixed_orifice, temperatures[k]);
          first[k].record = chain.solve(0, dp, hotter);
          first[k].state = chain.state();
          if (!first[k].state)
            continue;
          hotter = first[k].state->fields;
          for (const auto &[model, state] : hotter_of_model)
            if (model != first[k].state->model)
              first[k].other_models.push_back(state);
          hotter_of_model.insert_or_assign(first[k].state->model, *first[k].state);
        }
      return first;
    }

    /// The path's states as bytes, for broadcast_bytes from the rank that computed them (boost
    /// serialization, as common/sweep's gathering of rows; the members of FlowFields and State below).
    std::vector<char> pack_states(const std::vector<OrificeFirstCase> &first)
    {
      std::vector<char> converged; // per temperature (a std::optional has no boost serialisation)
      std::vector<Chain::State> states;
      std::vector<std::vector<Chain::State>> other_models;
      for (const auto &f : first)
        {
          converged.push_back(f.state.has_value());
          if (f.state)
            states.push_back(*f.state);
          other_models.push_back(f.other_models);
        }
      std::ostringstream out;
      boost::archive::binary_oarchive archive(out);
      archive << converged << states << other_models;
      const std::string bytes = out.str();
      return {bytes.begin(), bytes.end()};
    }

    /// pack_states' bytes back into the path's cases (without their records).
    std::vector<OrificeFirstCase> unpack_states(const std::vector<char> &bytes)
    {
      std::istringstream in(std::string(bytes.begin(), bytes.end()));
      boost::archive::binary_iarchive archive(in);
      std::vector<char> converged;
      std::vector<Chain::State> states;
      std::vector<std::vector<Chain::State>> other_models;
      archive >> converged >> states >> other_models;
      if (other_models.size() != converged.size())
        throw std::logic_error("flow: the orifice path's states were not unpacked whole");
      std::vector<OrificeFirstCase> out(converged.size());
      auto next = states.begin();
      for (std::size_t k = 0; k < converged.size(); ++k)
        {
          if (converged[k])
            out[k].state = std::move(*next++);
          out[k].other_models = std::move(other_models[k]);
        }
      return out;
    }

    /// The fixed orifice's other pressure differences at one temperature, in increasing order, from
    /// the first case's state (or from rest if it failed), offered the path's states of the other
    /// flow models.
    CaseRows orifice_chain(const ValveDescription &valve, double T, const OrificeFirstCase &first)
    {
      Chain chain(valve, PilotGeometry::fixed_orifice, T);
      if (first.state)
        chain.resume(*first.state);
      for (const auto &other : first.other_models)
        chain.offer(other);
      CaseRows records;
      const auto dps = scaled(valve.sweeps.field_orifice_pressure_fractions, span(valve));
      for (std::size_t j = 1; j < dps.size(); ++j)
        records.push_back(chain.solve(0, dps[j]));
      return records;
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
      const std::vector<OrificeFirstCase> states = unpack_states(broadcast_bytes(bytes, root));
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

  } // namespace

  PilotTables compute_pilot_field_tables(const ValveDescription &valve, const std::string &variant)
  {
    const auto [orifice, nozzle] = run_chains(valve);
    write_case_summary(valve, PilotGeometry::fixed_orifice, orifice, variant);
    write_case_summary(valve, PilotGeometry::nozzle_flapper, nozzle, variant);
    report_counts("fixed-orifice", orifice, valve.pilot.field_solution.cavitation);
    report_counts("nozzle-flapper", nozzle, valve.pilot.field_solution.cavitation);
    return {fixed_orifice_table(valve, orifice), nozzle_flapper_table(valve, nozzle)};
  }
} // namespace servodrift::flow
