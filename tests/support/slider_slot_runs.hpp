// Test support: a slider scan through slots on the host (ensemble/slider/slider_slot_sweep.hpp), each
// member on a host team — the bits a GPU team of that size gives (kernels/lanes/team.hpp).
#pragma once

#include <cstddef>
#include <vector>

#include "ensemble/slider/slider_slot_sweep.hpp"
#include "ensemble/slider/slider_team_member.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/models/slider/slider_model.hpp"
#include "kernels/models/slider/slider_on_teams.hpp"
#include "kernels/steppers/rosenbrock_tableaus.hpp"
#include "kernels/steppers/team_integrator.hpp"
#include "kernels/steppers/team_rosenbrock.hpp"
#include "support/parallel_members.hpp"

namespace rotorsweep::testing {

/// Chunks of slider slots on a host team of `ranks` with the scene's stepper (as the GPU's slider), at most
/// `chunk` members at a time, on every core; tables stay where they are.
template <bool Inertial>
class HostTeamSliderDevice final : public ensemble::SliderSlotDevice {
 public:
  using Integrator =
      kernels::TeamIntegrator<kernels::HostTeam,
                              kernels::TeamRosenbrock<kernels::HostTeam, kernels::SliderModel<double, Inertial>>>;
  using Driver = ensemble::SliderTeamMember<kernels::HostTeam, Integrator>;

  HostTeamSliderDevice(std::size_t ranks, std::size_t chunk) : ranks_(ranks), chunk_(chunk) {}

  std::size_t chunk_members(const ensemble::SliderSlotSchedule&) override { return chunk_; }
  std::vector<kernels::SubstrateTableView> place_tables(
      const std::vector<const kernels::SubstrateTable*>& tables) override {
    std::vector<kernels::SubstrateTableView> views;
    for (const auto* table : tables) views.push_back(table ? table->view() : kernels::SubstrateTableView{});
    return views;
  }
  void start(ensemble::SliderSlotChunk& chunk, std::size_t) override {
    const ensemble::SliderSlotViews views = chunk.views();
    for_each_member_in_parallel(chunk.count(), [&](std::size_t k) {
      std::vector<double> storage(Driver::storage_size(chunk.schedule(), ranks_));
      kernels::HostTeam crew(ranks_);
      Driver::run(crew, chunk.schedule(), views, k, storage.data(), storage.size());
    });
  }
  double finish(ensemble::SliderSlotChunk&, std::size_t) override { return 0.0; }  // start ran the members

 private:
  std::size_t ranks_, chunk_;
};

/// Every member of the scene's plan through slots on host teams of `ranks`, `chunk` members at a time.
inline std::vector<ensemble::SliderMember> slider_on_host_teams(const ensemble::SliderScene& scene,
                                                                std::size_t ranks, std::size_t chunk) {
  std::vector<std::size_t> all(scene.member_count());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
  std::vector<ensemble::SliderMember> members(all.size());
  const auto finished = [&](std::vector<ensemble::SliderMember>&& block) {
    for (auto& m : block) members[m.plan_index] = std::move(m);
  };
  const auto build_table = [](const ensemble::SliderScene& variant, ensemble::SliderSize size, double h,
                              double dy, double ddepth) {
    return ensemble::substrate_table<double>(variant, size, h, dy, ddepth);
  };
  if (scene.overdamped) {
    HostTeamSliderDevice<false> device(ranks, chunk);
    ensemble::run_slider_members_in_slots(scene, all, {}, finished, device, build_table);
  } else {
    HostTeamSliderDevice<true> device(ranks, chunk);
    ensemble::run_slider_members_in_slots(scene, all, {}, finished, device, build_table);
  }
  return members;
}

}  // namespace rotorsweep::testing
