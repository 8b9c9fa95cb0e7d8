// The slider as a problem of the lane scheduler (docs/architecture.md "Layers"): one member per lane,
// stopped and sampled on the sample grid; friction and energy balance per period in SI (docs/model.md §9).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "ensemble/engine/integration_loop.hpp"
#include "ensemble/engine/member_progress.hpp"
#include "ensemble/engine/rerun_queue.hpp"
#include "ensemble/slider/slider_member_summary.hpp"
#include "ensemble/slider/slider_sample_grid.hpp"
#include "ensemble/slider/slider_scene.hpp"
#include "ensemble/slider/slider_shadow.hpp"
#include "ensemble/slider/slider_sweep.hpp"
#include "kernels/lanes/angles.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/models/slider/slider_model.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/lane_status.hpp"

namespace rotorsweep::ensemble {

/// What a lane runs: plan member `plan_index`, or (`shadow`) that member's shadow run.
struct SliderRun {
  std::size_t plan_index = 0;
  bool shadow = false;
  SliderRun(std::size_t index = 0, bool is_shadow = false) : plan_index(index), shadow(is_shadow) {}
};

/// Members (plan indices) of one slider size on the lanes of an IntegrationLoop over
/// SliderModel<V, Inertial, Pairs> with Stepper, for LaneScheduler: each member's stops are its speed's
/// sample grid's (`grids`, one per speed), where its lane is sampled (drive force, order parameters, energy;
/// its quadratures at period boundaries); it retires after the last sample. Lanes sampled in the same step
/// attempt share one evaluation of the model. With shadow runs a finished member is held until its shadow
/// (the same member at tolerances × s, queued before the plan's next) has run, then retires with its error.
template <class V, bool Inertial, class Stepper, class Pairs = kernels::DirectPairs<V>>
class SliderProblem {
 public:
  using Model = kernels::SliderModel<V, Inertial, Pairs>;
  using Loop = IntegrationLoop<Model, kernels::AdaptiveIntegrator<Model, Stepper>>;
  using Member = SliderRun;
  using Result = SliderMember;
  static constexpr std::size_t width = Loop::width;

  /// `stopped()`, where given, is asked while a substrate table is built (kernels::SubstrateTableStopped).
  SliderProblem(const SliderScene& scene, const std::vector<SliderSampleGrid>& grids, SliderSize size,
                std::function<bool()> stopped = {})
      : scene_(scene),
        stopped_(std::move(stopped)),
        units_(scene),
        grids_(grids),
        size_(size),
        rotors_(kernels::SliderGrid{size.columns, size.rows}.rotors()),
        loop_(Inertial ? 2 * rotors_ : rotors_, settings(scene), kernels::SliderGrid{size.columns, size.rows},
              slider_placement(scene)),
        f_(loop_.dimension()),
        q_(loop_.dimension()),
        torques_(rotors_),
        lanes_(width) {}

  bool refill() const { return true; }
  std::optional<Member> take_queued() { return reruns_.take(); }
  bool has_queued() const { return reruns_.queued() > 0; }

  /// Puts plan member `run.plan_index` (or its shadow run) into lane l: its substrate table, its speed's
  /// grid and damping, its start; its schedule is one stop per sample.
  StopSchedule start(std::size_t l, Member run, bool) {
    Lane& lane = lanes_[l];
    lane.member = slider_plan_member(scene_, run.plan_index);
    lane.shadow = run.shadow;
    const SliderScene variant = slider_variant(scene_, lane.member.index.speed, lane.member.index.damping);
    lane.grid = &grids_[lane.member.index.speed];
    lane.table = table(variant, lane.member.index);
    const kernels::SliderParameters parameters = slider_parameters(variant, lane.table->view());
    if (scene_.forces) build_gradient_tables(l);
    if (!primed_) {  // lanes never started compute along with this member's tables
      for (std::size_t other = 0; other < width; ++other) {
        lanes_[other].table = lane.table;
        loop_.set_parameters(other, parameters);
        if (scene_.forces) {
          lanes_[other].gradient = lane.gradient;
          set_gradient_tables(other);
        }
      }
      primed_ = true;
    }
    std::vector<double> y0(loop_.dimension(), 0.0);
    const std::vector<double> theta = slider_start(scene_, lane.member.index);
    std::copy(theta.begin(), theta.end(), y0.begin());
    loop_.start(l, parameters, y0);
    if (run.shadow) loop_.set_tolerance_scale(l, shadow_tolerance_scale);
    loop_.set_stop(l, lane.grid->stops.front());
    const std::size_t samples = lane.grid->stops.size();
    size_slider_series(lane.member, scene_, samples);
    lane.sample = 0;
    lane.boundaries = {};
    return {int(samples), 0, false};
  }

  void step() {
    loop_.step();
    evaluated_ = false;
  }
  bool failed(std::size_t l) const { return loop_.failed(l); }
  bool any_stop_reached() const { return loop_.any_stop_reached(); }
  bool stop_reached(std::size_t l) const { return loop_.stop_reached(l); }

  /// Lane l reached its next sample: records it (and a period boundary's quadratures). A scan has no
  /// steady test: false.
  bool close_stop(std::size_t l) {
    Lane& lane = lanes_[l];
    const std::size_t k = lane.sample++;
    record_sample(l, k);
    if (lane.grid->boundary(k)) {
      lane.boundaries.impulse.push_back(loop_.quadrature(l, Model::impulse_index));
      lane.boundaries.dissipation.push_back(loop_.quadrature(l, Model::dissipation_index));
      lane.boundaries.energy.push_back(kernels::lane_get(energy_, l));
    }
    return false;
  }

  void next_stop(std::size_t l) { loop_.set_stop(l, lanes_[l].grid->stops[lanes_[l].sample]); }

  /// Retires lane l's member: a failed member's remaining samples hold its frozen state (every
  /// observable over periods is NaN); then its summaries, in SI.
  template <class Retire>
  void finish(std::size_t l, const MemberProgress&, bool, Retire& retire) {
    Lane& lane = lanes_[l];
    SliderMember& m = lane.member;
    m.status = std::string(kernels::status_name(loop_.status(l)));
    m.steps_accepted = loop_.steps_accepted(l);
    m.steps_rejected = loop_.steps_rejected(l);
    const bool ok = m.status == "ok";
    for (std::size_t k = lane.sample; k < lane.grid->stops.size(); ++k) record_sample(l, k);
    summarize_slider_member(scene_, *lane.grid, lane.boundaries, ok, m);
    loop_.release(l);
    if (lane.shadow) {
      std::optional<SliderMember> primary =
          reruns_.finish(m.plan_index, [&](SliderMember& held) { take_slider_shadow(held, m); });
      retire(std::move(*primary));
    } else if (needs_slider_shadow(scene_, m)) {
      const std::size_t index = m.plan_index;
      reruns_.hold(index, std::move(m), {Member(index, true)});
    } else {
      retire(std::move(m));
    }
  }

 private:
  struct Lane {
    SliderMember member;
    bool shadow = false;  ///< the member's shadow run
    const SliderSampleGrid* grid = nullptr;                ///< its speed's
    std::shared_ptr<const kernels::SubstrateTable> table;  ///< kept while the model may read it
    /// With SliderScene::forces: the tables at shifted tracks (SliderModel::GradientTable order)
    std::array<std::shared_ptr<const kernels::SubstrateTable>, 4> gradient;
    std::size_t sample = 0;       ///< the next sample
    SliderBoundaries boundaries;  ///< so far
  };

  static typename Loop::Settings settings(const SliderScene& scene) {
    kernels::StepLimits limits;
    limits.h_max = kernels::two_pi / double(scene.samples_per_period);
    limits.max_steps = scene.max_steps;
    return {
        kernels::stepper_method<typename Stepper::Method>(scene.stepper), {scene.rtol, scene.atol}, limits};
  }

  /// The substrate table of a member at `index` of `variant`: the last one built where the member's
  /// speed and separation are the last one's (replicas come one after another in the plan), else a new one.
  std::shared_ptr<const kernels::SubstrateTable> table(const SliderScene& variant,
                                                       const SliderMemberIndex& index) {
    const std::pair key{index.speed, index.separation};
    if (!last_table_ || last_table_key_ != key) {
      last_table_ = std::make_shared<const kernels::SubstrateTable>(
          substrate_table<V>(variant, size_, scene_.separations[index.separation], 0.0, 0.0, stopped_));
      last_table_key_ = key;
    }
    return last_table_;
  }

  /// Lane l's member's four tables at shifted tracks, for the forces' y- and z-derivatives.
  void build_gradient_tables(std::size_t l) {
    Lane& lane = lanes_[l];
    const double h = lane.member.separation;
    for (std::size_t g = 0; g < 4; ++g)
      lane.gradient[g] = std::make_shared<const kernels::SubstrateTable>(substrate_table<V>(
          scene_, size_, h, Model::gradient_shifts[g][0], Model::gradient_shifts[g][1], stopped_));
    set_gradient_tables(l);
  }
  void set_gradient_tables(std::size_t l) {
    std::array<kernels::SubstrateTableView, 4> views;
    for (std::size_t g = 0; g < 4; ++g) views[g] = lanes_[l].gradient[g]->view();
    loop_.model().set_gradient_tables(l, views);
  }

  /// The model at every lane's state, once per step attempt (the lanes sampled in it share it).
  void evaluate() {
    if (evaluated_) return;
    const auto& s = loop_.state();
    const Model& model = loop_.model();
    if (scene_.forces) model.forces(loop_.workspace(), s.y, s.t, force_x_, force_y_, force_z_);
    model.evaluate(loop_.workspace(), s.y, s.t, f_.data(), q_.data());
    model.order_parameters(s.y, along_x_, across_y_);
    energy_ = model.energy(loop_.workspace(), s.y, s.t) + model.kinetic_energy(s.y);
    if (scene_.rotor_observables()) {
      rotor_sums_ = {};
      model.rotor_observables_range(loop_.workspace(), 0, rotors_, rotor_sums_,
                                    scene_.torques ? torques_.data() : nullptr);
    }
    evaluated_ = true;
  }

  void record_sample(std::size_t l, std::size_t k) {
    evaluate();
    SliderMember& m = lanes_[l].member;
    record_slider_sample(m, k,
                         {kernels::lane_get(q_[Model::impulse_index], l), kernels::lane_get(along_x_, l),
                          kernels::lane_get(across_y_, l), kernels::lane_get(energy_, l)},
                         units_);
    if (scene_.angles)
      for (std::size_t r = 0; r < rotors_; ++r) m.angles[k * rotors_ + r] = loop_.component(l, r);
    if (scene_.rotor_observables()) {
      const auto at = [&](const V& v) { return kernels::lane_get(v, l); };
      const auto& sums = rotor_sums_;
      record_slider_rotor_sums(m, k,
                               {at(sums.substrate),
                                at(sums.pairs),
                                at(sums.field_axis),
                                at(sums.field_z),
                                {at(sums.moment_axis[0]), at(sums.moment_axis[1])},
                                {at(sums.moment_z[0]), at(sums.moment_z[1])},
                                {at(sums.torque[0]), at(sums.torque[1])}},
                               scene_);
      if (scene_.torques)
        for (std::size_t r = 0; r < rotors_; ++r)
          m.torques[k * rotors_ + r] = at(torques_[r]) * units_.energy;
    }
    if (scene_.forces)
      record_slider_forces(
          m, k,
          {kernels::lane_get(force_x_, l), kernels::lane_get(force_y_, l), kernels::lane_get(force_z_, l)},
          units_);
  }

  const SliderScene& scene_;
  std::function<bool()> stopped_;
  SliderUnits units_;
  const std::vector<SliderSampleGrid>& grids_;
  SliderSize size_;
  std::size_t rotors_;
  Loop loop_;
  kernels::lane_vector<V> f_, q_;  ///< the sample's evaluation: f and the quadratures' integrands
  V along_x_ = V(0.0), across_y_ = V(0.0), energy_ = V(0.0);
  V force_x_ = V(0.0), force_y_ = V(0.0), force_z_ = V(0.0);  ///< with SliderScene::forces
  typename Model::RotorObservables rotor_sums_;               ///< with SliderScene::rotor_observables()
  kernels::lane_vector<V> torques_;  ///< each rotor's substrate torque, with SliderScene::torques
  bool evaluated_ = false;           ///< f_, q_, the order parameters and energy_ are the current state's
  bool primed_ = false;              ///< every lane has parameters
  std::shared_ptr<const kernels::SubstrateTable> last_table_;  ///< the last table built ...
  std::pair<std::size_t, std::size_t> last_table_key_{};       ///< ... for this (speed, separation)
  std::vector<Lane> lanes_;
  RerunQueue<Member, SliderMember> reruns_;  ///< shadow runs waiting for a lane, their members held
};

}  // namespace rotorsweep::ensemble
