// run_sweep: variant by variant, dispatch from the scene's stepper to its instantiation (one
// generated translation unit per entry of kernels::steppers), or to the Langevin stepper at T > 0.
#include "ensemble/rows/sweep.hpp"

#include <algorithm>

#include "ensemble/gpu/gpu_backend.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

template <kernels::StepperId id>
SweepOutcome run_row_sweep(const Scene&, const VariantRange&, int, const SweepControl&, const ResultSink&);
SweepOutcome run_thermal_row_sweep(const Scene&, const VariantRange&, int, const SweepControl&,
                                   const ResultSink&);

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

SweepOutcome run_members(const Scene& scene, const MemberSource& source, int threads,
                         const SweepControl& control, const ResultSink& sink) {
  SweepOutcome outcome;
  std::size_t done_before = 0;
  for (std::size_t begin = 0; begin < source.count;) {
    // the variant's members are consecutive in plan order: find where they end
    const std::size_t variant = source.at(begin).variant;
    std::size_t low = begin + 1, high = source.count;
    while (low < high) {
      const std::size_t mid = low + (high - low) / 2;
      if (source.at(mid).variant == variant)
        low = mid + 1;
      else
        high = mid;
    }
    const VariantRange range{&source, begin, low};
    begin = low;
    if (control.stopped()) {
      outcome.interrupted = true;
      break;
    }
    const std::size_t before = done_before;
    const SweepControl part_control{[&](std::size_t done) {
                                      if (control.progress) control.progress(before + done);
                                    },
                                    control.stop, control.periods};
    if (scene.device == Device::gpu)
      outcome.append(run_gpu_row_sweep(scene, range, threads, part_control, sink));
    else if (scene.thermal.on())
      outcome.append(run_thermal_row_sweep(scene, range, threads, part_control, sink));
    else
      outcome.append(kernels::with_stepper_id(scene.stepper, [&]<kernels::StepperId id>() {
        return run_row_sweep<id>(scene, range, threads, part_control, sink);
      }));
    done_before += range.end - range.begin;
  }
  return outcome;
}

SweepOutcome run_sweep(const Scene& scene, const std::vector<Member>& members, int threads,
                       const ProgressCallback& progress, const std::atomic<bool>* stop) {
  std::vector<MemberResult> results(members.size());
  std::vector<char> finished(members.size(), 0);
  const MemberSource source{members.size(), [&](std::size_t k) { return members[k]; }, {}};
  auto outcome =
      run_members(scene, source, threads, SweepControl{progress, stop}, [&](MemberResult&& result) {
        // members are in plan order (sorted by index): find the result's position
        const auto at = std::lower_bound(members.begin(), members.end(), result.index,
                                         [](const Member& m, std::size_t index) { return m.index < index; });
        const auto k = std::size_t(at - members.begin());
        results[k] = std::move(result);
        finished[k] = 1;
      });
  outcome.results = std::move(results);
  outcome.finished = std::move(finished);
  return outcome;
}

}  // namespace rotorsweep::ensemble
