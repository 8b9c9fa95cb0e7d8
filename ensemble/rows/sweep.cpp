// run_sweep: variant by variant, dispatch from the scene's stepper to its family's instantiation (one
// generated translation unit per family of kernels::steppers), to the Langevin stepper at T > 0, or to
// the device executor its caller gave;
// each backend runs the reruns of its members itself (RowReruns: LaneScheduler, run_row_chunks).
#include "ensemble/rows/sweep.hpp"

#include <algorithm>
#include <stdexcept>

#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

template <kernels::StepperFamily family>
SweepOutcome run_row_sweep(const Scene&, const VariantRange&, const RunControl&, const ResultSink&);
SweepOutcome run_thermal_row_sweep(const Scene&, const VariantRange&, const RunControl&, const ResultSink&);

void SweepOutcome::append(SweepOutcome&& part) {
  for (auto& r : part.results) results.push_back(std::move(r));
  finished.insert(finished.end(), part.finished.begin(), part.finished.end());
  statistics.add(part.statistics);
  interrupted = interrupted || part.interrupted;
}

namespace {

/// The members of `range` on the scene's backend: `device`, or the CPU's lanes.
SweepOutcome run_range(const Scene& scene, const VariantRange& range, const RunControl& control,
                       const ResultSink& sink, const RowDevice* device) {
  if (scene.device == Device::gpu) {
    if (!device) throw std::invalid_argument("numerics.device = \"gpu\": run_members was given no GPU executor");
    return device->run_variant(scene, range, control, sink);
  }
  if (scene.thermal.on()) return run_thermal_row_sweep(scene, range, control, sink);
  return kernels::with_stepper_family(scene.stepper, [&]<kernels::StepperFamily family>() {
    return run_row_sweep<family>(scene, range, control, sink);
  });
}

}  // namespace

SweepOutcome run_members(const Scene& scene, const MemberSource& source, const RunControl& control,
                         const ResultSink& sink, const RowDevice* device) {
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
    // progress counts the members handed to the sink, a held member once its reruns are done
    const std::size_t before = done_before;
    RunControl part = control;
    if (control.progress) part.progress = [&](std::size_t done) { control.progress(before + done); };
    outcome.append(run_range(scene, range, part, sink, device));
    done_before += range.end - range.begin;
  }
  return outcome;
}

SweepOutcome run_sweep(const Scene& scene, const std::vector<Member>& members, const RunControl& control,
                       const RowDevice* device) {
  std::vector<MemberResult> results(members.size());
  std::vector<char> finished(members.size(), 0);
  const MemberSource source{members.size(), [&](std::size_t k) { return members[k]; }};
  auto outcome =
      run_members(scene, source, control, [&](MemberResult&& result) {
        // members are in plan order (sorted by index): find the result's position
        const auto at = std::lower_bound(members.begin(), members.end(), result.index,
                                         [](const Member& m, std::size_t index) { return m.index < index; });
        const auto k = std::size_t(at - members.begin());
        results[k] = std::move(result);
        finished[k] = 1;
      },
      device);
  outcome.results = std::move(results);
  outcome.finished = std::move(finished);
  return outcome;
}

}  // namespace rotorsweep::ensemble
