// Lane-parallel explicit Dormand–Prince 5(4) stepper: the non-stiff reference for tests and
// the benchmark that shows what stiffness costs. Quadrature states are plain extra components.
#pragma once

#include <cstddef>

#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/steppers/model_concept.hpp"
#include "kernels/steppers/dormand_prince_tableau.hpp"

namespace rotorsweep::kernels {

/// One attempted step of size h per lane. The first stage is evaluated afresh on every
/// attempt (no first-same-as-last reuse), since lanes accept and reject independently.
template <LaneModel System>
class DormandPrince5 {
 public:
  using V = typename System::lane_type;
  using Method = ExplicitTableau;  ///< its one tableau, dormand_prince5_tableau (the list's entry)
  static constexpr std::size_t nq = System::max_quadratures;  ///< storage; quadratures_ are carried

  ROTORSWEEP_HD DormandPrince5(const System& system, const ExplicitTableau&, LaneArena<V>& arena)
      : n_(system.dimension()),
        quadratures_(system.quadrature_count()),
        work_(n_, arena),
        argument_(arena.take(n_)),
        slopes_(arena.take(std::size_t(dormand_prince5_tableau.stages) * n_)),
        quad_slopes_(arena.take(std::size_t(dormand_prince5_tableau.stages) * nq + 1)) {}

  ROTORSWEEP_HD static constexpr const char* name() { return dormand_prince5_tableau.name; }
  ROTORSWEEP_HD static constexpr int order() { return dormand_prince5_tableau.order; }
  ROTORSWEEP_HD static constexpr int embedded_order() { return dormand_prince5_tableau.embedded_order; }
  /// Right-hand side evaluations per attempt: one per stage.
  ROTORSWEEP_HD static constexpr int evaluations() { return dormand_prince5_tableau.stages; }

  /// One step of size h. Returns every lane: an explicit method follows unstable directions
  /// (its error estimate sees them), so no lane needs the implicit steppers' extra check.
  ROTORSWEEP_HD lane_mask<V> attempt(const System& system, V t, V h, const V* y, const V* q, V* y_new,
                                     V* q_new, V* y_error, V* q_error) {
    const std::size_t n = n_;
    constexpr ExplicitTableau T = dormand_prince5_tableau;  // a local copy for device code
    for (int i = 0; i < T.stages; ++i) {
      for (std::size_t k = 0; k < n; ++k) argument_[k] = y[k];
      for (int j = 0; j < i; ++j) {
        if (T.a[i][j] == 0.0) continue;
        const V ha = h * V(T.a[i][j]);
        const V* kj = slopes_ + std::size_t(j) * n;
        for (std::size_t k = 0; k < n; ++k) argument_[k] += ha * kj[k];
      }
      system.evaluate(work_, argument_, t + V(T.c[i]) * h, slopes_ + std::size_t(i) * n,
                      quad_slopes_ + std::size_t(i) * quadratures_);
    }
    combine(h, y, n, slopes_, y_new, y_error);
    combine(h, q, quadratures_, quad_slopes_, q_new, q_error);
    return h == h;
  }

  /// The quadratures' integrands at the start of the last attempt (its first stage).
  ROTORSWEEP_HD const V* start_integrands() const { return quad_slopes_; }

 private:
  ROTORSWEEP_HD static void combine(V h, const V* start, std::size_t count, const V* slopes, V* result,
                                    V* error) {
    constexpr ExplicitTableau T = dormand_prince5_tableau;  // a local copy for device code
    for (std::size_t k = 0; k < count; ++k) {
      V sum(0.0), err(0.0);
      for (int i = 0; i < T.stages; ++i) {
        const V s = slopes[std::size_t(i) * count + k];
        if (T.b[i] != 0.0) sum += V(T.b[i]) * s;
        if (T.e[i] != 0.0) err += V(T.e[i]) * s;
      }
      result[k] = start[k] + h * sum;
      error[k] = h * err;
    }
  }

  std::size_t n_;
  std::size_t quadratures_;  ///< the model's carried quadratures
  typename System::Workspace work_;
  V *argument_, *slopes_, *quad_slopes_;
};

}  // namespace rotorsweep::kernels
