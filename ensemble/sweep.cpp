// run_sweep: variant by variant, dispatch from the scene's stepper to its instantiation (one
// generated translation unit per entry of kernels::steppers), or to the Langevin stepper at T > 0.
#include "ensemble/sweep.hpp"

#include "kernels/stepper_list.hpp"

namespace rotorsweep::ensemble {

template <kernels::StepperId id>
SweepOutcome run_row_sweep(const Scene&, const std::vector<Member>&, int, const SweepControl&);
SweepOutcome run_thermal_row_sweep(const Scene&, const std::vector<Member>&, int, const SweepControl&);

static_assert(ROTORSWEEP_STEPPER_COUNT == kernels::steppers::size,
              "the build generated one translation unit per entry of kernels::steppers");

void SweepOutcome::append(SweepOutcome&& part) {
  for (auto& r : part.results) results.push_back(std::move(r));
  finished.insert(finished.end(), part.finished.begin(), part.finished.end());
  statistics.wall_seconds += part.statistics.wall_seconds;
  statistics.lane_steps_busy += part.statistics.lane_steps_busy;
  statistics.lane_steps_total += part.statistics.lane_steps_total;
  statistics.threads = part.statistics.threads;
  statistics.lane_width = part.statistics.lane_width;
  interrupted = interrupted || part.interrupted;
}

SweepOutcome run_sweep(const Scene& scene, const std::vector<Member>& members, int threads,
                       const ProgressCallback& progress, const std::atomic<bool>* stop) {
  const auto variants = scene.variants();
  SweepOutcome outcome;
  std::size_t done_before = 0;
  for (std::size_t v = 0; v < variants.size(); ++v) {
    std::vector<Member> part;
    for (const auto& m : members)
      if (m.variant == v) part.push_back(m);
    if (part.empty()) continue;
    const SweepControl control{[&](std::size_t done) {
                                 if (progress) progress(done_before + done);
                               },
                               stop};
    if (control.stopped()) {
      outcome.results.resize(outcome.results.size() + part.size());
      outcome.finished.resize(outcome.finished.size() + part.size(), 0);
      outcome.interrupted = true;
      continue;
    }
    if (scene.thermal.on())
      outcome.append(run_thermal_row_sweep(scene, part, threads, control));
    else
      outcome.append(kernels::with_stepper_id(scene.stepper, [&]<kernels::StepperId id>() {
        return run_row_sweep<id>(scene, part, threads, control);
      }));
    done_before += part.size();
  }
  return outcome;
}

}  // namespace rotorsweep::ensemble
