// run_sweep: variant by variant, dispatch from the scene's stepper to its family's instantiation (one
// generated translation unit per family of kernels::steppers), or to the Langevin stepper at T > 0;
// on the GPU, members whose averaged periods slip get their shadow runs in a second pass (docs/numerics.md).
#include "ensemble/rows/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <mutex>

#include "ensemble/gpu/gpu_backend.hpp"
#include "ensemble/rows/shadow_attractor.hpp"
#include "ensemble/rows/shadow_run.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

template <kernels::StepperFamily family>
SweepOutcome run_row_sweep(const Scene&, const VariantRange&, int, const SweepControl&, const ResultSink&);
SweepOutcome run_thermal_row_sweep(const Scene&, const VariantRange&, int, const SweepControl&,
                                   const ResultSink&);

void SweepOutcome::append(SweepOutcome&& part) {
  for (auto& r : part.results) results.push_back(std::move(r));
  finished.insert(finished.end(), part.finished.begin(), part.finished.end());
  statistics.wall_seconds += part.statistics.wall_seconds;
  statistics.kernel_seconds += part.statistics.kernel_seconds;
  statistics.setup_seconds += part.statistics.setup_seconds;
  statistics.fill_seconds += part.statistics.fill_seconds;
  statistics.wait_seconds += part.statistics.wait_seconds;
  statistics.deliver_seconds += part.statistics.deliver_seconds;
  statistics.lane_steps_busy += part.statistics.lane_steps_busy;
  statistics.lane_steps_total += part.statistics.lane_steps_total;
  statistics.threads = part.statistics.threads;
  statistics.lane_width = part.statistics.lane_width;
  interrupted = interrupted || part.interrupted;
}

namespace {

/// The members of `range` on the scene's backend.
SweepOutcome run_range(const Scene& scene, const VariantRange& range, int threads,
                       const SweepControl& control, const ResultSink& sink) {
  if (scene.device == Device::gpu) return run_gpu_row_sweep(scene, range, threads, control, sink);
  if (scene.thermal.on()) return run_thermal_row_sweep(scene, range, threads, control, sink);
  return kernels::with_stepper_family(scene.stepper, [&]<kernels::StepperFamily family>() {
    return run_row_sweep<family>(scene, range, threads, control, sink);
  });
}

/// On the GPU (whose threads run a member from start to retirement) the members of one variant's range
/// whose averaged periods slipped wait for their shadow runs, which a second pass runs; the CPU lanes
/// run a shadow as soon as its primary retires (LaneScheduler).
class ShadowedRange {
 public:
  ShadowedRange(const Scene& scene, const VariantRange& range)
      : on_(scene.runs_shadows() && scene.device == Device::gpu), plan_(scene) {
    if (range.end > range.begin) limited_ = scene.symmetry_limited(range.source->at(range.begin).rtol);
  }

  /// Hands `result` to `sink`, or holds it for its shadow run.
  void take(MemberResult&& result, const ResultSink& sink) {
    if (!on_ || !needs_shadow(result)) return sink(std::move(result));
    const std::lock_guard guard(lock_);
    held_.emplace(result.index, std::move(result));
  }
  std::size_t held() const {
    const std::lock_guard guard(lock_);
    return held_.size();
  }

  /// The shadow runs of the held members: each integrates its primary's averaged periods again, from
  /// where they began, and its result completes its primary, which goes to `sink`.
  SweepOutcome run_shadows(const Scene& scene, int threads, const SweepControl& control,
                           const ResultSink& sink) {
    std::vector<Member> members;
    for (const auto& [index, primary] : held_) {
      Member m = plan_[index];
      m.rerun = Rerun::shadow;
      m.tolerance_scale = shadow_tolerance_scale;
      if (!primary.averaging_start.empty())
        m.start = std::make_shared<const std::vector<double>>(primary.averaging_start);
      members.push_back(std::move(m));
    }
    Scene averaged_periods = scene;
    averaged_periods.relax_periods = 0;
    averaged_periods.steady_tol = 0;
    const MemberSource shadows{members.size(), [&](std::size_t k) { return members[k]; }, {}};
    return run_range(averaged_periods, {&shadows, 0, members.size()}, threads, control,
                     [&](MemberResult&& shadow) {
                       MemberResult primary;
                       {
                         const std::lock_guard guard(lock_);
                         const auto at = held_.find(shadow.index);
                         primary = std::move(at->second);
                         held_.erase(at);
                       }
                       complete_with_shadow(primary, shadow, limited_);
                       sink(std::move(primary));
                     });
  }

 private:
  bool on_;
  bool limited_ = false;
  MemberPlan plan_;
  mutable std::mutex lock_;
  std::map<std::size_t, MemberResult> held_;
};

}  // namespace

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
    // progress counts the members handed to the sink: a held member counts once its shadow is done
    ShadowedRange shadowed(scene, range);
    const std::size_t before = done_before;
    const SweepControl first_pass{[&](std::size_t done) {
                                    if (control.progress) control.progress(before + done - shadowed.held());
                                  },
                                  control.stop, control.periods};
    outcome.append(run_range(scene, range, threads, first_pass,
                             [&](MemberResult&& result) { shadowed.take(std::move(result), sink); }));
    const std::size_t held = shadowed.held();
    if (held > 0 && !outcome.interrupted) {
      const std::size_t delivered = before + (range.end - range.begin) - held;
      const SweepControl second_pass{[&](std::size_t done) {
                                       if (control.progress) control.progress(delivered + done);
                                     },
                                     control.stop, control.periods};
      outcome.append(shadowed.run_shadows(scene, threads, second_pass, sink));
    }
    done_before += range.end - range.begin;
  }
  return outcome;
}

SweepOutcome run_sweep(const Scene& scene, const std::vector<Member>& members, int threads,
                       const ProgressCallback& progress, const std::atomic<bool>* stop,
                       std::atomic<std::size_t>* periods) {
  std::vector<MemberResult> results(members.size());
  std::vector<char> finished(members.size(), 0);
  const MemberSource source{members.size(), [&](std::size_t k) { return members[k]; }, {}};
  auto outcome =
      run_members(scene, source, threads, SweepControl{progress, stop, periods}, [&](MemberResult&& result) {
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
