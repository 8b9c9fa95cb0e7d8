// One slider member on a team of threads from its start to its retirement (docs/architecture.md
// "Teams"): SliderProblem's lane on a team — stops on its sample grid, samples (docs/model.md §9) as team
// sums.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "ensemble/slider/slider_member_summary.hpp"
#include "ensemble/slider/slider_slots.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/steppers/team_integrator.hpp"

namespace rotorsweep::ensemble {

/// Runs slider members on a team with Integrator (TeamIntegrator over TeamRosenbrock on
/// SliderModel<double, Inertial>): the member steps to each stop of its grid as SliderProblem's lane
/// does (the same step control, stops and budget), is sampled there — F, the order parameters and the
/// energy, and the rotor sums and the force where asked, from the ranks' sums; angles and torques
/// rotor by rotor — and keeps its impulse, dissipation and energy at period boundaries. A member that
/// fails keeps its frozen state's samples; the summaries are the host's (SliderSlotChunk).
template <class Team, class Integrator>
struct SliderTeamMember {
  using Model = typename Integrator::Model;

  /// Values of scratch a member of schedule s needs on a team of `ranks`, shared by the team.
  ROTORSWEEP_HD static std::size_t storage_size(const SliderSlotSchedule& s, std::size_t ranks) {
    return kernels::counted_storage<double>(
        [&](kernels::LaneArena<double>& arena) { const Parts parts(s, ranks, arena); });
  }

  /// Integrates chunk member k of `slots` to its retirement on `team` and writes its slots; `storage`
  /// (the team's, at least storage_size values) holds its vectors.
  ROTORSWEEP_HD static void run(Team& team, const SliderSlotSchedule& s, const SliderSlotViews& slots,
                                std::size_t k, double* storage, std::size_t capacity) {
    kernels::LaneArena<double> arena(storage, capacity);
    Parts parts(s, team.size(), arena);
    team.sync();
    Model& model = parts.model;
    model.set_lane(0, slots.parameters[k]);
    if (s.forces) {
      std::array<kernels::SubstrateTableView, 4> gradient;
      for (std::size_t g = 0; g < 4; ++g) gradient[g] = slots.gradients[4 * k + g];
      model.set_gradient_tables(0, gradient);
    }
    const std::size_t dim = model.dimension();
    kernels::TeamMemberState state;
    state.y = parts.y;
    team.each([&](std::size_t r) {
      const kernels::TeamRows part = kernels::team_rows(dim, team.size(), r);
      for (std::size_t i = part.begin; i < part.end; ++i) state.y[i] = slots.y0[k * dim + i];
    });
    std::size_t boundary = 0;
    for (std::size_t stop = 0; stop < s.stops; ++stop) {
      state.t_stop = slots.stops[stop];
      parts.integrator.advance(team, model, state);  // nothing once the member has failed: it stays frozen
      const std::size_t at = k * s.stops + stop;
      double* v = slots.samples + at * s.sample_values();
      const double energy = sample(team, model, parts, state, s, slots, v, at);
      const bool at_boundary = slots.boundary[stop] != 0;
      team.one([&] {
        if (at_boundary) {
          double* b = slots.boundary_values + (k * s.boundaries + boundary) * slider_boundary_values;
          b[0] = state.quad[Model::impulse_index];
          b[1] = state.quad[Model::dissipation_index];
          b[2] = energy;
        }
      });
      if (at_boundary) ++boundary;
    }
    team.one([&] {
      slots.status[k] = std::uint8_t(state.status);
      slots.steps[2 * k] = state.steps_accepted;
      slots.steps[2 * k + 1] = state.steps_rejected;
    });
  }

 private:
  /// Values each rank adds to a sample: F, E, Σ θ̇², the two alignments, then the rotor observables'
  /// ten sums and the force's three components.
  static constexpr std::size_t sums_per_rank = 18;

  /// What a member builds over the team's scratch (storage_size counts the same).
  struct Parts {
    Model model;
    Integrator integrator;
    typename Model::Workspace work;  ///< the samples' evaluation
    double* y;                       ///< the state θ (and ω)
    double* partial;                 ///< each rank's parts of a sample's sums (sums_per_rank values each)

    ROTORSWEEP_HD Parts(const SliderSlotSchedule& s, std::size_t ranks, kernels::LaneArena<double>& arena)
        : model(s.grid, s.placement, arena),
          integrator(model, ranks, s.methods.template get<typename Integrator::Method>(),
                     {s.rtol, s.atol}, {.h_max = s.h_max, .max_steps = s.max_steps}, s.first_step_scale, arena),
          work(model.dimension(), arena),
          y(arena.take(model.dimension())),
          partial(arena.take(sums_per_rank * ranks)) {}
  };

  /// Samples the member's state into `values` (the slot's sample_values(): F, the order parameters,
  /// the energy, then the rotor sums and the force where the schedule asks for them), its angles and
  /// torques into sample `at` of those slots; returns the energy. Each rank takes its rotors' field and
  /// torques, then its parts of the sums; the team adds them.
  ROTORSWEEP_HD static double sample(Team& team, const Model& model, Parts& parts,
                                     const kernels::TeamMemberState& state, const SliderSlotSchedule& s,
                                     const SliderSlotViews& slots, double* values, std::size_t at) {
    const std::size_t n = model.rotors();
    const auto each_rank = [&](auto&& part) {
      team.each([&](std::size_t r) {
        const kernels::TeamRows rotors = kernels::team_rows(n, team.size(), r);
        part(rotors.begin, rotors.end, parts.partial + sums_per_rank * r);
      });
    };
    each_rank([&](std::size_t begin, std::size_t end, double*) {
      model.prepare_range(parts.work, state.y, state.t, false, begin, end);
    });
    double* torques = s.torques ? slots.torques + at * n : nullptr;
    each_rank([&](std::size_t begin, std::size_t end, double* mine) {
      model.torque_range(parts.work, begin, end);
      mine[0] = model.force_range(parts.work, begin, end);
      mine[1] = model.energy_range(parts.work, begin, end);
      mine[2] = model.velocity_squares(state.y, begin, end);
      mine[3] = mine[4] = 0.0;
      model.alignment_range(state.y, begin, end, mine[3], mine[4]);
      if (s.rotor_sums || s.torques) {
        typename Model::RotorObservables sums;
        model.rotor_observables_range(parts.work, begin, end, sums, torques);
        const double own[10] = {sums.substrate,      sums.pairs,          sums.field_axis,  sums.field_z,
                                sums.moment_axis[0], sums.moment_axis[1], sums.moment_z[0], sums.moment_z[1],
                                sums.torque[0],      sums.torque[1]};
        for (std::size_t c = 0; c < 10; ++c) mine[5 + c] = own[c];
      }
      if (s.forces) {
        mine[15] = mine[16] = mine[17] = 0.0;
        model.forces_range(parts.work, state.t, begin, end, mine[15], mine[16], mine[17]);
      }
      if (s.angles)
        for (std::size_t r = begin; r < end; ++r) slots.angles[at * n + r] = state.y[r];
    });
    const auto total = [&](std::size_t c) {
      return team.sum([&](std::size_t r) { return parts.partial[sums_per_rank * r + c]; });
    };
    double order_x = total(3), order_y = total(4);
    model.mean_alignment(order_x, order_y);
    const double energy = total(1) + model.kinetic_energy_of(total(2));
    const double force = total(0);
    double rotor_sums[10] = {}, force_sums[3] = {};
    if (s.rotor_sums)
      for (std::size_t c = 0; c < 10; ++c) rotor_sums[c] = total(5 + c);
    if (s.forces)
      for (std::size_t c = 0; c < 3; ++c) force_sums[c] = total(15 + c);
    team.one([&] {
      values[0] = force;
      values[1] = order_x;
      values[2] = order_y;
      values[3] = energy;
      if (s.rotor_sums)
        for (std::size_t c = 0; c < 10; ++c) values[s.rotor_sums_at() + c] = rotor_sums[c];
      if (s.forces)
        for (std::size_t c = 0; c < 3; ++c) values[s.forces_at() + c] = force_sums[c];
    });
    return energy;
  }
};

}  // namespace rotorsweep::ensemble
