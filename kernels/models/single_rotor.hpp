// One overdamped rotor in a rotating field, g dθ/dt = A sin(θ - t) (docs/model.md §1, "A second
// model"): the row model's substrate term alone, with a closed-form solution to test the engine.
#pragma once

#include <array>
#include <cstddef>

#include "kernels/lanes/angles.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/lane_math.hpp"
#include "kernels/linear/diagonal_jacobian.hpp"
#include "kernels/steppers/model_concept.hpp"
#include "kernels/models/rows/integrals.hpp"

namespace rotorsweep::kernels {

/// State θ (one component, an angle); one quadrature, the drive integral R = A ∫ sin(θ - t) dt,
/// which equals g (θ(t1) - θ(t0)). Satisfies LaneModel.
template <class V>
class SingleRotor {
 public:
  using lane_type = V;
  using Jacobian = DiagonalJacobian<V>;
  static constexpr double period = two_pi;
  static constexpr std::size_t max_quadratures = 1;

  struct Parameters {
    double A = 1.0;
    double g = 1.0;
  };

  struct Workspace {
    static constexpr std::size_t storage_size(std::size_t) { return 0; }
    ROTORSWEEP_HD Workspace(std::size_t, LaneArena<V>&) {}
  };

  static constexpr std::size_t storage_size(std::size_t) { return 0; }  ///< it keeps no per-row values
  ROTORSWEEP_HD SingleRotor(std::size_t, LaneArena<V>&) {}

  ROTORSWEEP_HD void set_lane(std::size_t lane, const Parameters& p) {
    lane_set(A_, lane, p.A);
    lane_set(inv_g_, lane, 1.0 / p.g);
  }
  ROTORSWEEP_HD std::size_t dimension() const { return 1; }
  /// It carries R alone (the row models' drive quadrature), which steers the step.
  ROTORSWEEP_HD static constexpr Integrals integrals() { return dissipation_only; }
  ROTORSWEEP_HD static constexpr std::size_t quadrature_count() { return 1; }
  ROTORSWEEP_HD static constexpr bool error_controlled(std::size_t) { return true; }
  ROTORSWEEP_HD static constexpr StateScale scale(std::size_t) { return StateScale::absolute; }
  /// R is weighed as the row models' R (kernels/models/rows/row_quadratures.hpp).
  ROTORSWEEP_HD static constexpr StateScale quadrature_scale(std::size_t) {
    return StateScale::capped_relative;
  }

  ROTORSWEEP_HD void evaluate(Workspace&, const V* theta, V t, V* f, V* qdot) const {
    V s, c;
    lane_sincos(theta[0] - t, s, c);
    f[0] = inv_g_ * A_ * s;
    qdot[0] = A_ * s;
  }

  ROTORSWEEP_HD void linearize(Workspace& w, const V* theta, V t, V* f, V* qdot, Jacobian& J, V* df_dt,
                               V* dq_dtheta, V* dq_dt) const {
    evaluate(w, theta, t, f, qdot);
    V s, c;
    lane_sincos(theta[0] - t, s, c);
    J.diag(0) = inv_g_ * A_ * c;
    df_dt[0] = lane_neg(inv_g_) * A_ * c;
    dq_dtheta[0] = A_ * c;
    dq_dt[0] = lane_neg(A_) * c;
  }

 private:
  V A_ = V(1.0), inv_g_ = V(1.0);
};

}  // namespace rotorsweep::kernels
