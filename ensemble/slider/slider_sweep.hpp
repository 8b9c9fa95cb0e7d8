// The slider scan (docs/model.md §9 "Observables"): members (separation × replica) in SIMD lanes over
// OpenMP threads; friction per substrate period, energy balance, order parameters and time series in SI.
#pragma once

#include <cmath>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "ensemble/engine/run_control.hpp"
#include "ensemble/slider/slider_scene.hpp"

namespace rotorsweep::ensemble {

class SliderDevice;  // ensemble/slider/slider_slot_sweep.hpp

/// One member's results, SI units.
struct SliderMember {
  std::size_t plan_index = 0;  ///< its row in the plan (SliderMemberIndex's order)
  SliderMemberIndex index;     ///< its place in the plan (size, speed, damping, separation, replica)
  SliderSize size;
  double speed = 0.0;       ///< v, m/s
  double damping = 0.0;     ///< γ, kg m²/s
  double separation = 0.0;  ///< h, m
  double friction = 0.0;    ///< mean drive force over the averaged periods of sliding, N
  /// With shadow runs (SliderScene::shadow_runs): the shadow's friction and friction's error estimate,
  /// N (ensemble/slider/slider_shadow.hpp; NaN without them or where the member failed)
  double friction_shadow = std::nan(""), friction_error = std::nan("");
  std::vector<double> period_friction, period_work, period_dissipation, period_stored;  ///< N, J, J, J
  std::vector<double> period_balance;   ///< (work − dissipation − stored) / max(|work|, dissipation)
  double order_x = 0.0, order_y = 0.0;  ///< mean over the averaged periods' samples
  /// Per sample of the scan's timeline (SliderTimeline: NaN before the first sample of the member's speed)
  std::vector<double> friction_series, order_x_series, order_y_series, energy_series;
  std::vector<double> angles;  ///< samples × rotors, when asked for
  /// Per sample, when asked for (SliderScene::energies, field, sublattices): the substrate energy
  /// −Σ m·B and the pairs' energy (J); the mean B_∥ and B_z at the rotors' sites (T); the mean unit
  /// moment (its in-plane and z parts) and substrate torque (N m) of the even rows j = 0, 2, … and of
  /// the odd rows.
  std::vector<double> substrate_energy_series, pair_energy_series, field_axis_series, field_z_series;
  std::vector<double> moment_axis_even_series, moment_z_even_series, torque_even_series;
  std::vector<double> moment_axis_odd_series, moment_z_odd_series, torque_odd_series;
  std::vector<double> torques;  ///< samples × rotors: each rotor's substrate torque (N m), when asked for
  /// The substrate's force on the slider per sample (N; SliderScene::forces; F_x = −friction), and the
  /// per-period means of F_y and F_z (trapezoidal over the period's samples).
  std::vector<double> force_x_series, force_y_series, force_z_series, period_force_y, period_force_z;
  double steps_accepted = 0.0, steps_rejected = 0.0;
  std::string status = "ok";
};

/// Member `plan_index` of the scene's plan before it runs: its place, size, speed, damping and separation.
SliderMember slider_plan_member(const SliderScene& scene, std::size_t plan_index);

/// When the members are sampled: each speed's sample grid, with `samples_per_period` samples per
/// substrate period through the start of sliding, on one axis of `samples` columns aligned at the
/// start of sliding (a slower speed samples its rest fewer times: its first columns are NaN).
struct SliderTimeline {
  std::size_t samples = 0;                        ///< columns of every series
  std::vector<std::vector<double>> sample_times;  ///< per speed: s since the start of the rest, or NaN
  std::size_t periods = 0;                        ///< whole substrate periods of sliding (every speed)
  std::vector<double> period;                     ///< per speed: a / v, s
};
SliderTimeline slider_timeline(const SliderScene& scene);

/// Bytes one thread of a CPU scan works in besides its members' series: the largest lane block of its
/// sizes (its integration loop's arena: O(n²) dense, O(n) matrix-free) and the substrate tables its lanes
/// may hold (one each, four more with observables.forces, and the one being built) at the closest
/// separation and the longest path.
double slider_thread_bytes(const SliderScene& scene);
/// The most members a CPU thread holds at once: a SIMD lane block's, or 1 where every size is matrix-free.
std::size_t slider_thread_lanes(const SliderScene& scene);

/// Runs the members `plan_indices` (ascending) in lane blocks of one size each and hands the finished
/// members to `finished` (one call at a time, in any order). A member's results do not depend on which
/// members share its block. control.claim, where set, is asked for positions in plan_indices within a
/// group run together (one size; on the GPU one size and speed); control.stops counts the samples members
/// take. An exception in a worker (std::bad_alloc) stops the other blocks and is rethrown here. With
/// SliderScene::device = gpu the members run on `device` (an error where there is none), a chunk at a time.
RunOutcome run_slider_members(const SliderScene& scene, const std::vector<std::size_t>& plan_indices,
                              const RunControl& control,
                              const std::function<void(std::vector<SliderMember>&&)>& finished,
                              const SliderDevice* device = nullptr);

/// Every member of the scene's plan, held in memory.
struct SliderResult {
  SliderTimeline timeline;
  std::vector<SliderMember> members;  ///< in plan order; members left out by a stop are empty
  RunOutcome outcome;
};
SliderResult run_slider_scan(const SliderScene& scene, const RunControl& control = {},
                             const SliderDevice* device = nullptr);

}  // namespace rotorsweep::ensemble
