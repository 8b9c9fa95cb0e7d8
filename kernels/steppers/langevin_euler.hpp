// Overdamped Langevin dynamics of a lane model at temperature T (docs/model.md §7, docs/numerics.md
// "Temperature"): the linearly implicit Euler scheme for dθ = f dt + √(2T/g) dW, fixed steps.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "kernels/lanes/counter_random.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/models/model_concept.hpp"
#include "kernels/steppers/lane_state.hpp"

namespace rotorsweep::kernels {

/// Advances every lane by
///     (I − h J(θ_n, t_n)) (θ_{n+1} − θ_n) = h f(θ_n, t_n) + √(2T/g) ΔW_n,   ΔW_n ~ N(0, h I),
/// the drift-implicit (Rosenbrock–Euler) scheme: strong and weak order 1 for this additive noise
/// (Itô and Stratonovich readings coincide), and unconditionally stable for the stiff gradient
/// drift, which it solves with the model's own Jacobian factorisation. Quadratures take the left
/// point, q += h qdot(θ_n, t_n). Each period of a lane is split into steps_for(settings, g)
/// equal steps: at least `steps_per_period`, and steps no longer than step_fraction · g, the time
/// scale of a slip (the last steps of a period are evened out to land on t_stop). ΔW of a lane comes from its
/// own counter-based stream: row j of step k is normal number k N + j, so a member's path does not depend on
/// its lane, block, thread or device.
template <LaneModel Model>
class LangevinEuler {
 public:
  using V = typename Model::lane_type;
  static constexpr std::size_t nq = Model::max_quadratures;  ///< storage; the model's carried ones step
  static constexpr bool stochastic = true;

  struct Settings {
    double temperature = 0.0;  ///< T in units of the energy scale
    int steps_per_period = 2000;
    double step_fraction = 0.25;  ///< steps no longer than this times g
  };

  /// The steps per period of a member with damping g.
  ROTORSWEEP_HD static double steps_for(const Settings& settings, double g) {
    const double by_g = std::ceil(Model::period / (settings.step_fraction * g));
    return by_g > double(settings.steps_per_period) ? by_g : double(settings.steps_per_period);
  }

  ROTORSWEEP_HD LangevinEuler(const Model& model, Settings settings, LaneArena<V>& arena)
      : settings_(settings),
        work_(model.dimension(), arena),
        jacobian_(model.dimension(), arena),
        f_(arena.take(model.dimension())),
        df_dt_(arena.take(model.dimension())),
        dq_dtheta_(arena.take(model.dimension() * nq)),
        qdot_(arena.take(nq + 1)),
        dq_dt_(arena.take(nq + 1)) {}

  /// A member enters `lane`: its noise stream key and its g (the noise amplitude is √(2T/g)).
  ROTORSWEEP_HD void start_lane(std::size_t lane, std::uint64_t key, double g) {
    keys_[lane] = key;
    lane_set(amplitude_, lane, lane_sqrt(2.0 * settings_.temperature / g));
    lane_set(h_nominal_, lane, Model::period / steps_for(settings_, g));
  }

  /// One step of every lane that is ok and short of its t_stop. Returns the lanes that stepped.
  ROTORSWEEP_HD lane_mask<V> attempt(const Model& model, LaneState<V>& s) {
    const lane_mask<V> active = s.stepping();
    if (!lane_any(active)) return active;
    const std::size_t n = s.dimension();
    // the steps left in this period, all equal: lands on t_stop without a sliver step
    const V remaining = s.t_stop - s.t;
    const V steps_left = lane_max(V(1.0), lane_round(remaining / h_nominal_ + V(0.25)));
    const V h = lane_select(active, remaining / steps_left, h_nominal_);
    s.h = lane_select(active, h, s.h);

    model.linearize(work_, s.y, s.t, f_, qdot_, jacobian_, df_dt_, dq_dtheta_, dq_dt_);
    const V inv_h = V(1.0) / h;
    // right-hand side f + amplitude ΔW / h with ΔW = √h ξ
    const V noise_factor = amplitude_ * lane_sqrt(inv_h);
    for (std::size_t j = 0; j < n; ++j) {
      const V xi = lane_from<V>([&](std::size_t l) {
        const RandomStream stream = RandomStream::from_key(keys_[l]);
        return stream.normal(std::uint64_t(lane_get(s.steps_accepted, l)) * n + j);
      });
      f_[j] = f_[j] + noise_factor * xi;
    }
    jacobian_.factor(inv_h);
    jacobian_.solve(f_);  // (I/h − J) Δ = f + amplitude ΔW / h

    V checksum(0.0);
    for (std::size_t j = 0; j < n; ++j) checksum += f_[j];
    const lane_mask<V> finite = lane_isfinite(checksum);
    const lane_mask<V> step = active & finite;
    for (std::size_t j = 0; j < n; ++j) s.y[j] = lane_select(step, s.y[j] + f_[j], s.y[j]);
    for (std::size_t p = 0; p < model.quadrature_count(); ++p)
      s.quad[p] = lane_select(step, s.quad[p] + h * qdot_[p], s.quad[p]);
    s.t = lane_select(step, lane_select(steps_left <= V(1.0), s.t_stop, s.t + h), s.t);
    s.steps_accepted += lane_select(step, V(1.0), V(0.0));
    for (std::size_t l = 0; l < lane_width<V>; ++l)
      if (mask_get(active, l) && !mask_get(finite, l)) s.status[l] = LaneStatus::non_finite;
    return step;
  }

  /// The quadratures' integrands at the start of the last step, in the lanes that stepped.
  ROTORSWEEP_HD const V* start_integrands() const { return qdot_; }

 private:
  Settings settings_;
  typename Model::Workspace work_;
  typename Model::Jacobian jacobian_;
  V *f_, *df_dt_, *dq_dtheta_, *qdot_, *dq_dt_;
  std::array<std::uint64_t, lane_width<V>> keys_{};
  V amplitude_ = V(0.0);  ///< √(2T/g) per lane
  V h_nominal_ = V(1.0);  ///< the lane's step: period / steps_for(settings, g)
};

}  // namespace rotorsweep::kernels
