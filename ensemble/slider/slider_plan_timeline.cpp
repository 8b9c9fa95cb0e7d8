// The members of a slider scene's plan and the grid they are sampled on, without lanes (compiled once
// for every instruction set): slider_plan_member and slider_timeline of slider_sweep.hpp (docs/model.md §9).
#include <algorithm>
#include <cmath>
#include <vector>

#include "ensemble/slider/slider_sample_grid.hpp"
#include "ensemble/slider/slider_sweep.hpp"

namespace rotorsweep::ensemble {

SliderMember slider_plan_member(const SliderScene& scene, std::size_t plan_index) {
  SliderMember m;
  m.plan_index = plan_index;
  std::size_t rest = plan_index;
  const auto take = [&](std::size_t count) {
    const std::size_t at = rest % count;
    rest /= count;
    return at;
  };
  m.index.replica = take(scene.replicas);
  m.index.separation = take(scene.separations.size());
  m.index.damping = take(scene.dampings.size());
  m.index.speed = take(scene.speeds.size());
  m.index.size = rest;
  m.size = scene.sizes[m.index.size];
  m.speed = scene.speeds[m.index.speed];
  m.damping = scene.dampings[m.index.damping];
  m.separation = scene.separations[m.index.separation];
  return m;
}

SliderTimeline slider_timeline(const SliderScene& scene) {
  SliderTimeline timeline;
  std::vector<std::vector<double>> times;
  for (std::size_t v = 0; v < scene.speeds.size(); ++v) {
    const SliderScene variant = slider_variant(scene, v, 0);
    const SliderUnits units(variant);
    const SliderSampleGrid grid(variant);
    timeline.periods = grid.periods;
    timeline.period.push_back(variant.spacing / variant.speed);
    times.emplace_back();
    for (const double t : grid.stops) times.back().push_back(t * units.time);
    timeline.samples = std::max(timeline.samples, grid.stops.size());
  }
  for (auto& t : times) t.insert(t.begin(), timeline.samples - t.size(), std::nan(""));
  timeline.sample_times = std::move(times);
  return timeline;
}

}  // namespace rotorsweep::ensemble
