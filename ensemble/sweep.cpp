// run_sweep: dispatch from the scene's stepper name to its instantiation (sweep_<stepper>.cpp).
#include "ensemble/sweep.hpp"

#include "kernels/stepper_choice.hpp"

namespace rotorsweep::ensemble {

template <kernels::StepperKind kind>
SweepOutcome run_sweep_with(const Scene&, const std::vector<Member>&, int, const ProgressCallback&);

namespace {

SweepOutcome run_variant(const Scene& scene, const std::vector<Member>& members, int threads,
                         const ProgressCallback& progress) {
  switch (scene.stepper) {
    case kernels::StepperKind::ros2:
      return run_sweep_with<kernels::StepperKind::ros2>(scene, members, threads, progress);
    case kernels::StepperKind::dopri5:
      return run_sweep_with<kernels::StepperKind::dopri5>(scene, members, threads, progress);
    case kernels::StepperKind::rodas4p2:
      return run_sweep_with<kernels::StepperKind::rodas4p2>(scene, members, threads, progress);
    case kernels::StepperKind::rodas4: break;
  }
  return run_sweep_with<kernels::StepperKind::rodas4>(scene, members, threads, progress);
}

}  // namespace

void SweepOutcome::append(SweepOutcome&& part) {
  for (auto& r : part.results) results.push_back(std::move(r));
  statistics.wall_seconds += part.statistics.wall_seconds;
  statistics.lane_steps_busy += part.statistics.lane_steps_busy;
  statistics.lane_steps_total += part.statistics.lane_steps_total;
  statistics.threads = part.statistics.threads;
  statistics.lane_width = part.statistics.lane_width;
}

SweepOutcome run_sweep(const Scene& scene, const std::vector<Member>& members, int threads,
                       const ProgressCallback& progress) {
  const auto variants = scene.variants();
  SweepOutcome outcome;
  std::size_t done_before = 0;
  for (std::size_t v = 0; v < variants.size(); ++v) {
    std::vector<Member> part;
    for (const auto& m : members)
      if (m.variant == v) part.push_back(m);
    if (part.empty()) continue;
    const ProgressCallback part_progress = [&](std::size_t done) {
      if (progress) progress(done_before + done);
    };
    outcome.append(run_variant(scene.for_variant(variants[v]), part, threads, part_progress));
    done_before += part.size();
  }
  return outcome;
}

}  // namespace rotorsweep::ensemble
