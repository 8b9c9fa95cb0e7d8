// The form of the adaptive steps (AdaptiveSteps: error norm and step control of step_control.hpp) for one
// member whose rows live in registers across its lanes (docs/architecture.md "Register kernels").
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/steppers/adaptive_steps.hpp"
#include "kernels/steppers/lane_status.hpp"
#include "kernels/steppers/rosenbrock_tableaus.hpp"
#include "kernels/steppers/step_control.hpp"
#include "kernels/steppers/team_member_form.hpp"

namespace rotorsweep::kernels {

/// One member in registers: its rows' angles (each lane its R slots, padding 0), and what every lane
/// keeps alike (TeamMemberState's scalars): the quadratures by kind, time, step size, stopping time,
/// counts and status.
template <class V, std::size_t R>
struct WarpMemberState {
  static constexpr std::size_t kinds = TeamMemberState::max_quadratures;
  V y[R];
  double quad[kinds] = {};
  double t = 0.0, h = 0.0, t_stop = 0.0;  ///< h = 0 asks for an automatic first step
  double steps_accepted = 0.0, steps_rejected = 0.0;
  double tolerance_scale = 1.0;
  LaneStatus status = LaneStatus::ok;
  ROTORSWEEP_HD bool stepping() const { return status == LaneStatus::ok && t < t_stop; }
};

/// A vector of a member's R slots per lane, in registers (every index a constant after unrolling).
template <class V, std::size_t R>
struct RegisterVector {
  V v[R];
  template <class Arena>
  ROTORSWEEP_HD RegisterVector(std::size_t, Arena&) {}
  ROTORSWEEP_HD V* data() { return v; }
};

/// What a member in registers builds its vectors from: nothing (a RegisterVector holds its own).
struct RegisterArena {};

/// AdaptiveSteps' form for a member of a WarpRows model in registers: each lane its R slots, every sum
/// over slots in order and then across the lanes in the warp's butterfly order (every lane decides alike),
/// every loop over slots, stages and quadratures unrolled to compile-time indices (the quadratures by
/// kind, those the member does not carry skipped). Its stepper is WarpRosenbrock.
template <class Model>
class WarpMemberForm {
 public:
  using value_type = typename Model::V;
  using scalar_type = double;
  using W = typename Model::Warp;
  static constexpr std::size_t R = Model::slots_per_lane;
  using State = WarpMemberState<value_type, R>;
  using Context = Model&;
  using Arena = RegisterArena;
  using Vector = RegisterVector<value_type, R>;
  static constexpr std::size_t max_quadratures = Model::kinds;

  template <class... Shape>
  ROTORSWEEP_HD WarpMemberForm(std::size_t, Arena&, const Shape&...) {}

  ROTORSWEEP_HD static const Model& model(Context c) { return c; }
  ROTORSWEEP_HD static constexpr std::size_t quadratures(std::size_t) { return Model::kinds; }
  ROTORSWEEP_HD static bool carries(Context c, std::size_t kind) { return c.carries(kind); }
  template <class Part>
  ROTORSWEEP_HD void rows(Context, Part&& part) const {
    part(std::size_t(0), R);
  }
  template <class Part>
  ROTORSWEEP_HD double sum(Context, Part&& part) const {
    return W::sum(part(std::size_t(0), R));
  }
  template <class Stepper, class... Arguments>
  ROTORSWEEP_HD bool step(Stepper& stepper, Context c, Arguments... arguments) const {
    return stepper.attempt(c, arguments...);
  }
  template <class Stepper>
  ROTORSWEEP_HD double first_rate(Context c, Stepper&, const State& s, value_type*, double* q) const {
    value_type f[R];
    c.evaluate(s.y, s.t, f, q);
    value_type largest(1e-300);
    ROTORSWEEP_UNROLL
    for (std::size_t r = 0; r < R; ++r) largest = lane_max(largest, lane_abs(f[r]));
    return W::max(largest);
  }
  ROTORSWEEP_HD static LaneStatus& status(State& s, std::size_t) { return s.status; }
};

/// One member's adaptive steps in registers with a WarpRosenbrock stepper (AdaptiveSteps: the first
/// step, error norm, acceptance, step-size control and failure flags), decided alike in every lane.
template <class Model, class Stepper>
class WarpIntegrator : public AdaptiveSteps<WarpMemberForm<Model>, Stepper> {
  using Steps = AdaptiveSteps<WarpMemberForm<Model>, Stepper>;

 public:
  ROTORSWEEP_HD WarpIntegrator(const RosenbrockTableau& table, Tolerances tol, StepLimits limits,
                               double first_step_scale, RegisterArena arena = {})
      : Steps(Model::slots_per_lane, table, tol, limits, first_step_scale, arena) {}
};

}  // namespace rotorsweep::kernels
