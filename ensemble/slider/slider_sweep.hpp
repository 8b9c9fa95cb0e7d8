// The slider scan (docs/model.md §9 "Observables"): members (separation × replica) in SIMD lanes over
// OpenMP threads; friction per substrate period, energy balance, order parameters and time series in SI.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "ensemble/slider/slider_scene.hpp"

namespace rotorsweep::ensemble {

/// One member's results, SI units.
struct SliderMember {
  SliderMemberIndex index;  ///< its place in the plan (size, separation, replica)
  SliderSize size;
  double separation = 0.0;  ///< h, m
  double friction = 0.0;    ///< mean drive force over the whole periods of sliding, N
  std::vector<double> period_friction, period_work, period_dissipation, period_stored;  ///< N, J, J, J
  std::vector<double> period_balance;   ///< (work − dissipation − stored) / max(|work|, dissipation)
  double order_x = 0.0, order_y = 0.0;  ///< mean over the samples while sliding
  std::vector<double> friction_series, order_x_series, order_y_series, energy_series;  ///< per sample
  std::vector<double> angles;  ///< samples × rotors, when asked for
  double steps_accepted = 0.0, steps_rejected = 0.0;
  std::string status = "ok";
};

struct SliderResult {
  std::vector<double> sample_times;   ///< s (0 = start of the rest)
  std::size_t periods = 0;            ///< whole substrate periods of sliding
  double period = 0.0;                ///< a / v, s
  std::vector<SliderMember> members;  ///< size-major, then separation, then replica
  double seconds = 0.0;               ///< wall time of the integration
  bool stopped = false;               ///< stopped() turned true: members of blocks not run are empty
};

/// Runs every member of the scene on `threads` threads (0: all); `progress(done, total)` after each lane
/// block; once `stopped()` is true no further block starts (the running ones finish).
SliderResult run_slider_scan(const SliderScene& scene, int threads,
                             const std::function<void(std::size_t, std::size_t)>& progress = {},
                             const std::function<bool()>& stopped = {});

}  // namespace rotorsweep::ensemble
