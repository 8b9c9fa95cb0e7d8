// The row model as a problem of the lane scheduler (docs/architecture.md "Layers"): how a member of
// a row scene enters a lane, what its steps and periods record, and its result (docs/model.md §3).
#pragma once

#include <algorithm>
#include <cstddef>
#include <deque>
#include <limits>
#include <memory>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "ensemble/engine/integration_loop.hpp"
#include "ensemble/engine/member_progress.hpp"
#include "ensemble/rows/lane_observers.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/member_result.hpp"
#include "ensemble/rows/member_summary.hpp"
#include "ensemble/rows/observables.hpp"
#include "ensemble/rows/row_profile_observer.hpp"
#include "ensemble/rows/row_reruns.hpp"
#include "ensemble/rows/scene.hpp"
#include "ensemble/rows/steady_dissipation.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

/// The step observers a loop's model can feed, switched on by what it carries: the alignment
/// extremes where it integrates ρ̄, the dissipation's error estimate where it integrates R with
/// error control (the slip counter is always there; at T > 0 the error of D is statistical and
/// comes from the periods, see SummaryRules).
template <class Loop>
auto quadrature_observers(const Scene& scene, const Member& variant, kernels::Integrals carried) {
  return std::tuple(AlignmentObserver<Loop>(carried.alignment, carried.alignment_index()),
                    DissipationErrorObserver<Loop>(
                        carried.drive && !Loop::stochastic, carried.drive_index(),
                        kernels::stepper_swing_error_factors[scene.stepper] * variant.rtol, variant.atol));
}

/// The integrator settings of a variant: the stepper's tableau, tolerances and step limits for the adaptive
/// integrators, temperature and steps per period for the Langevin stepper.
template <class Integrator>
typename Integrator::Settings integrator_settings(const Scene& scene, const Member& variant) {
  if constexpr (Integrator::stochastic)
    return {scene.thermal.temperature, scene.thermal.steps_per_period, scene.thermal.step_fraction};
  else
    return {kernels::stepper_method<typename Integrator::Method>(scene.stepper),
            {variant.rtol, variant.atol},
            {.h_max = scene.h_max, .max_steps = scene.max_steps, .controller = scene.controller}};
}

/// Members of one variant (one dimension and tolerances) of a row scene on the lanes of an
/// IntegrationLoop<Model, Integrator>, for LaneScheduler. `Setup` gives the model's construction
/// arguments after the dimension and the arena (model_arguments(), a tuple: the row models'
/// quadratures) and turns a member into the model's parameters and its initial state:
/// initial_state(member) and parameters(member, y0), and with a stochastic integrator its noise
/// stream: noise_key(member). The model reports the quadratures it carries (integrals()). A finished
/// member may be held for its reruns (RowReruns: shadow run, slower rerun), which are queued for the
/// next free lane and complete it.
template <kernels::LaneModel Model, class Integrator, class Setup>
class RowProblem {
 public:
  using Loop = IntegrationLoop<Model, Integrator>;
  using Member = ensemble::Member;
  using Result = MemberResult;
  static constexpr std::size_t width = Loop::width;

  RowProblem(const Scene& scene, const Member& variant, Setup setup)
      : scene_(scene),
        setup_(std::move(setup)),
        settings_(integrator_settings<Integrator>(scene, variant)),
        loop_(
            std::apply([&](const auto&... arguments) { return Loop(variant.rows, settings_, arguments...); },
                       setup_.model_arguments())),
        carried_(loop_.model().integrals()),
        channels_(quadrature_channels(carried_)),
        observers_(quadrature_observers<Loop>(scene, variant, carried_)),
        slips_(variant.rows, scene.slip_rate, scene.has(Observable::slips), scene.slip_kinds),
        profiles_(variant.rows, scene.row_profiles),
        period_schedule_(scene.period_schedule()),
        shadow_schedule_(scene.shadow_schedule()),
        reruns_(scene, Loop::stochastic, variant.rtol),
        end_capacity_(end_state_capacity(scene.average_periods)),
        rules_(summary_rules(scene, Loop::stochastic, Loop::period, profiles_.enabled())),
        lanes_(width) {}

  /// Whether a retired member's lane takes the next member at once (else the whole block waits).
  bool refill() const { return scene_.refill; }

  /// A rerun waiting for a lane, taken before the plan's next member.
  std::optional<Member> take_queued() { return reruns_.take_queued(); }
  bool has_queued() const { return reruns_.queued() > 0; }

  /// Puts `member` into lane l (a plan member or a queued rerun); returns its period schedule.
  StopSchedule start(std::size_t l, const Member& member, bool) {
    const std::vector<double> y0 = setup_.initial_state(member);
    loop_.start(l, setup_.parameters(member, y0), y0);
    if (member.tolerance_scale != 1.0) loop_.set_tolerance_scale(l, member.tolerance_scale);
    if constexpr (Loop::stochastic) {
      loop_.start_noise(l, setup_.noise_key(member), member.g);
      slips_.set_rate(
          l, thermal_slip_rate(scene_.slip_rate, scene_.thermal.temperature, member.g, loop_.noise_step(l)));
    }
    for_each_observer([&](auto& observer) { observer.start(loop_, l); });
    slips_.set_damping(l, member.g);
    profiles_.start(loop_, l);
    Lane& lane = lanes_[l];
    lane.member = member;
    lane.history.clear();
    lane.end_states.clear();
    lane.profiles.clear();
    lane.steady = SteadyDissipation{scene_.steady_tol};
    return member.rerun == Rerun::shadow || member.rerun == Rerun::probe ? shadow_schedule_ : period_schedule_;
  }

  /// One step attempt of every lane, with the observers.
  void step() {
    std::apply([&](auto&... observer) { loop_.step(observer..., slips_, profiles_); }, observers_);
  }

  bool failed(std::size_t l) const { return loop_.failed(l); }
  bool any_stop_reached() const { return loop_.any_stop_reached(); }
  bool stop_reached(std::size_t l) const { return loop_.stop_reached(l); }

  /// Records the period lane l just closed; returns whether its dissipation agrees with the period
  /// before's (the steady test, SteadyDissipation).
  bool close_stop(std::size_t l) {
    PeriodRecord record;
    record_quadratures(
        channels_, carried_, record, [&](std::size_t p) { return loop_.quadrature(l, p); }, Loop::period,
        kernels::lane_get(loop_.state().t, l));
    for_each_observer([&](auto& observer) { observer.end_period(l, record); });
    if constexpr (Loop::stochastic)
      record[Channel::dissipation_error] = std::numeric_limits<double>::quiet_NaN();

    auto& ends = lanes_[l].end_states;
    if (ends.size() == end_capacity_) ends.erase(ends.begin());
    ends.emplace_back(loop_.dimension());
    for (std::size_t k = 0; k < loop_.dimension(); ++k) ends.back()[k] = loop_.component(l, k);

    if (profiles_.enabled()) {
      auto& profiles = lanes_[l].profiles;
      profiles.push_back(profiles_.take_period(l));
      if (profiles.size() > std::size_t(scene_.average_periods)) profiles.pop_front();
    }

    auto& history = lanes_[l].history;
    history.push_back(record);
    forget_old_periods(history);
    return lanes_[l].steady.close(record.dissipation());
  }

  /// Lane l goes on to its next period (wrapped with scene.wrap_angles).
  void next_stop(std::size_t l) { loop_.next_period(l, scene_.wrap_angles); }

  /// Retires lane l's member, which closed `progress.stops()` periods (`settled`: it met its
  /// schedule): its result goes to retire(), or, where it needs reruns, waits for them; a rerun's
  /// result completes its primary's, which retires with its last rerun.
  template <class Retire>
  void finish(std::size_t l, const MemberProgress& progress, bool settled, Retire& retire) {
    MemberResult result = summarize_lane(l, progress, settled);
    const Member member = std::move(lanes_[l].member);
    release_lane(l);
    reruns_.finish(member, std::move(result), retire,
                   [&](const Member& m) { return setup_.initial_state(m); });
  }

 private:
  struct Lane {
    Member member;
    std::vector<PeriodRecord> history;  ///< every period with period_series, else the last ones
    std::vector<std::vector<double>>
        end_states;  ///< θ at the last period ends (up to end_capacity_, oldest first)
    std::deque<std::vector<double>> profiles;  ///< row profiles of the last average_periods periods
    SteadyDissipation steady;                  ///< the steady test over its periods
  };

  template <class F>
  void for_each_observer(F&& f) {
    std::apply([&](auto&... observer) { (f(observer), ...); }, observers_);
    f(slips_);
  }

  /// Without period_series only the averaged periods (and the two the steady test compares) are
  /// needed: the history is cut back to them whenever it reaches twice that length, so a lane
  /// holds at most 2 max(average_periods, 2) records however long its member runs.
  void forget_old_periods(std::vector<PeriodRecord>& history) const {
    if (scene_.period_series) return;
    const std::size_t keep = std::size_t(std::max(scene_.average_periods, 2));
    if (history.size() >= 2 * keep) history.erase(history.begin(), history.end() - std::ptrdiff_t(keep));
  }

  /// The result of the member in lane l, from its records.
  MemberResult summarize_lane(std::size_t l, const MemberProgress& progress, bool settled) {
    Lane& lane = lanes_[l];
    RetiredLane retired;
    retired.index = lane.member.index;
    retired.status = loop_.status(l);
    retired.settled = settled;
    retired.periods = progress.stops();
    retired.steps_accepted = loop_.steps_accepted(l);
    retired.steps_rejected = loop_.steps_rejected(l);
    retired.theta.resize(loop_.dimension());
    for (std::size_t k = 0; k < loop_.dimension(); ++k) retired.theta[k] = loop_.component(l, k);
    retired.history = std::move(lane.history);
    keep_end_states(retired, std::move(lane.end_states), scene_.average_periods);
    retired.profiles.assign(std::make_move_iterator(lane.profiles.begin()),
                            std::make_move_iterator(lane.profiles.end()));
    retired.links = profiles_.links();
    return retired_member_result(std::move(retired), rules_);
  }

  void release_lane(std::size_t l) {
    Lane& lane = lanes_[l];
    lane.history.clear();
    lane.end_states.clear();
    lane.profiles.clear();
    loop_.release(l);
  }

  const Scene& scene_;
  Setup setup_;
  typename Loop::Settings settings_;
  Loop loop_;
  kernels::Integrals carried_;   ///< the quadratures the model carries
  QuadratureChannels channels_;  ///< the channels they fill
  decltype(quadrature_observers<Loop>(std::declval<const Scene&>(), std::declval<const Member&>(),
                                      kernels::Integrals{})) observers_;
  SlipObserver<Loop> slips_;
  RowProfileObserver<Loop> profiles_;
  StopSchedule period_schedule_;
  StopSchedule shadow_schedule_;  ///< a shadow run's: the averaged periods, no steady test
  RowReruns reruns_;              ///< queued reruns, primaries waiting for them
  std::size_t end_capacity_;  ///< period ends a lane keeps (end_state_capacity)
  SummaryRules rules_;        ///< how a retired lane becomes a result
  std::vector<Lane> lanes_;
};

}  // namespace rotorsweep::ensemble
