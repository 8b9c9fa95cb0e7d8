// The reruns a row member may need, for every backend (docs/numerics.md "The global error of D",
// "Symmetry-limited members", docs/regimes.md "Jumps and smooth slips"): its shadow run, its symmetry
// probe and its slower rerun, queued in one RerunQueue.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "ensemble/engine/rerun_queue.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/member_result.hpp"
#include "ensemble/rows/scene.hpp"
#include "ensemble/rows/shadow_attractor.hpp"
#include "ensemble/rows/shadow_run.hpp"
#include "ensemble/rows/slip_kinds.hpp"
#include "ensemble/rows/smooth_alternation_window.hpp"
#include "ensemble/rows/symmetry_probe.hpp"

namespace rotorsweep::ensemble {

/// Decides which finished members run again and completes them with their reruns' results: a member
/// whose averaged periods slip (with shadow runs on) gets its shadow run; one that slips or ends on a
/// symmetric set, in a scene without a physical perturbation above rtol, its symmetry probe; one that
/// slips in every averaged period (with observables.slip_kinds) its slower rerun. Its result is held
/// until they have finished. Not thread-safe (RerunQueue).
class RowReruns {
 public:
  /// The reruns of a variant's members (tolerance `rtol`), with a stochastic integrator none.
  RowReruns(const Scene& scene, bool stochastic, double rtol)
      : scene_(&scene),
        shadows_(scene.runs_shadows() && !stochastic),
        slower_(scene.slip_kinds && !stochastic),
        probes_(runs_probes(scene, stochastic, rtol)) {}

  /// Member `member` finished with `result`: a primary goes to retire(result) or waits for its reruns
  /// (a shadow run and a probe start where its averaged periods began, or at initial_state(member)
  /// where they began at the start); a rerun completes its primary, which goes to retire() with its
  /// last rerun (a probed primary with its symmetry verdict).
  template <class Retire, class InitialState>
  void finish(const Member& member, MemberResult&& result, Retire&& retire, InitialState&& initial_state) {
    if (member.rerun != Rerun::none) {
      std::optional<MemberResult> primary = queue_.finish(member.index, [&](MemberResult& held) {
        if (member.rerun == Rerun::shadow)
          complete_with_shadow(held, result);
        else if (member.rerun == Rerun::probe)
          take_probe(held, result);
        else
          take_slower_rerun(held, result, smooth_alternation_possible(*scene_, member.A));
      });
      if (!primary) return;
      settle_symmetry(*primary);
      retire(std::move(*primary));
      return;
    }
    std::vector<Member> reruns;
    const auto averaged_periods_again = [&](Rerun kind) {
      Member again = member;
      again.rerun = kind;
      again.start = std::make_shared<const std::vector<double>>(
          result.averaging_start.empty() ? initial_state(member) : result.averaging_start);
      return again;
    };
    if (shadows_ && needs_shadow(result)) {
      Member shadow = averaged_periods_again(Rerun::shadow);
      shadow.tolerance_scale = shadow_tolerance_scale;
      reruns.push_back(std::move(shadow));
    }
    if (probes_ && needs_probe(result, scene_->couplings.open)) reruns.push_back(averaged_periods_again(Rerun::probe));
    if (slower_ && needs_slower_rerun(result)) {
      Member slower = member;  // the same start, disorder and schedule
      slower.rerun = Rerun::slower;
      slower.g *= slower_damping_scale;
      reruns.push_back(std::move(slower));
    }
    if (reruns.empty()) {
      retire(std::move(result));
      return;
    }
    queue_.hold(member.index, std::move(result), std::move(reruns));
  }

  /// The next rerun waiting for a lane or a chunk.
  std::optional<Member> take_queued() { return queue_.take(); }
  std::size_t queued() const { return queue_.queued(); }
  std::size_t held() const { return queue_.held(); }

 private:
  const Scene* scene_;
  bool shadows_;           ///< members whose averaged periods slip get shadow runs
  bool slower_;            ///< members that slip in every averaged period get slower reruns
  bool probes_;            ///< symmetry probes run (runs_probes)
  RerunQueue<Member, MemberResult> queue_;
};

}  // namespace rotorsweep::ensemble
