// Test support: a scene's members run on the host through one chunk of member slots, as the GPU
// backend runs them: by one thread's driver (DeviceMember), or by a host team (TeamMember); a host
// device for the GPU's chunk loop (run_row_chunks).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

#include "ensemble/engine/member_forms.hpp"
#include "ensemble/gpu/device_drivers.hpp"
#include "ensemble/rows/device_member.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/member_slots.hpp"
#include "ensemble/rows/row_chunks.hpp"
#include "ensemble/rows/team_member.hpp"
#include "kernels/lanes/team.hpp"
#include "support/parallel_members.hpp"

namespace rotorsweep::testing {

/// Every member of the scene (one variant) through run(schedule, views, k) in one chunk of slots, one
/// after another, or with `parallel` on every core (for_each_member_in_parallel: no Catch2 assertion in
/// run); the schedule's first-step scale is Integrator's.
template <class Integrator, class Run>
std::vector<ensemble::MemberResult> through_slots(const ensemble::Scene& scene, Run&& run,
                                                  bool parallel = false) {
  if (scene.variants().size() != 1) throw std::logic_error("through_slots: a scene of one variant");
  const ensemble::MemberPlan plan(scene);
  std::vector<ensemble::Member> members;
  for (std::size_t i = 0; i < plan.size(); ++i) members.push_back(plan[i]);
  const auto schedule = ensemble::slot_schedule(
      scene, members.front(), ensemble::device_first_step_scale<Integrator>(scene, members.front()));
  ensemble::SlotChunk chunk(schedule, members.size());
  chunk.fill(scene, members);
  const ensemble::SlotViews views = chunk.views();
  if (parallel)
    for_each_member_in_parallel(members.size(), [&](std::size_t k) { run(schedule, views, k); });
  else
    for (std::size_t k = 0; k < members.size(); ++k) run(schedule, views, k);
  std::vector<ensemble::MemberResult> results;
  for (std::size_t k = 0; k < members.size(); ++k) results.push_back(chunk.result(scene, k));
  return results;
}

/// Every member of the scene on a host team of `ranks` with TeamIntegrator (its first-step scale that
/// of Integrator, the same integrator on one lane), members on every core: the bits a GPU team of that
/// size gives (kernels/lanes/team.hpp).
template <class Integrator, class TeamIntegrator>
std::vector<ensemble::MemberResult> on_host_team(const ensemble::Scene& scene, std::size_t ranks) {
  using Team = ensemble::TeamMember<kernels::HostTeam, TeamIntegrator>;
  return through_slots<Integrator>(
      scene,
      [&](const ensemble::SlotSchedule& s, const ensemble::SlotViews& v, std::size_t k) {
        if (!Team::team_schedule_fits(s))
          throw std::logic_error("on_host_team: a team cannot run this scene");
        std::vector<double> storage(Team::storage_size(s, ranks));
        kernels::HostTeam crew(ranks);
        Team::run(crew, s, v, k, storage.data(), storage.size());
      },
      true);
}

/// on_host_team with the scene's (linearly implicit) stepper on the scene's row model.
inline std::vector<ensemble::MemberResult> on_host_team(const ensemble::Scene& scene, std::size_t ranks) {
  if (kernels::stepper_family(scene.stepper) != kernels::StepperFamily::rosenbrock)
    throw std::logic_error("on_host_team: a team runs linearly implicit steppers");
  constexpr auto family = kernels::StepperFamily::rosenbrock;
  return ensemble::with_device_model(scene, [&]<class Model>() {
    using Stepper = ensemble::DeviceTeamStepper<family, kernels::HostTeam, Model>;
    return on_host_team<ensemble::DeviceAdaptiveIntegrator<family, Model>,
                        kernels::TeamIntegrator<kernels::HostTeam, Stepper>>(scene, ranks);
  });
}

/// A RowSlotDevice on the host (ensemble/rows/row_chunks.hpp): start runs every member of the chunk
/// with run(schedule, views, k) on every core; it records each started chunk's stops (a plan chunk's
/// periods, a shadow chunk's averaged periods) and members, in order.
template <class Run>
struct HostSlotDevice final : ensemble::RowSlotDevice {
  explicit HostSlotDevice(Run r) : run(std::move(r)) {}
  Run run;
  std::vector<std::pair<int, std::size_t>> chunks;

  void start(ensemble::SlotChunk& chunk, std::size_t) override {
    chunks.emplace_back(chunk.schedule().periods.stops, chunk.count());
    const ensemble::SlotSchedule schedule = chunk.schedule();
    const ensemble::SlotViews views = chunk.views();
    for_each_member_in_parallel(chunk.count(), [&](std::size_t k) { run(schedule, views, k); });
  }
  double finish(ensemble::SlotChunk&, std::size_t) override { return 0.0; }
};

/// Every member of the scene one by one with DeviceMember<Model, Integrator>: the CPU lanes' bits.
template <class Model, class Integrator>
std::vector<ensemble::MemberResult> on_one_thread(const ensemble::Scene& scene) {
  using Driver = ensemble::DeviceMember<Model, Integrator>;
  static_assert(ensemble::ThreadMemberForm<Driver, ensemble::SlotSchedule, ensemble::SlotViews>);
  return through_slots<Integrator>(
      scene, [&](const ensemble::SlotSchedule& s, const ensemble::SlotViews& v, std::size_t k) {
        std::vector<double> storage(Driver::storage_size(s));
        Driver::run(s, v, k, storage.data(), storage.size());
      });
}

}  // namespace rotorsweep::testing
