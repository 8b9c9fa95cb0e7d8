// What the steppers and the driver need of a model (docs/architecture.md "Models"): the LaneModel
// and LaneJacobian concepts, and how a state component's error is weighted.
#pragma once

#include <concepts>
#include <cstddef>

#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"

namespace rotorsweep::kernels {

/// How the error of one state component or quadrature is measured against the tolerances: angles
/// (and other quantities that live on a fixed scale) absolutely, s = atol + rtol; velocities and
/// other components that can be large relatively, s = atol + rtol·max(|y|, |y_new|); a quantity
/// whose wanted accuracy does not grow with its running value relatively but never more loosely
/// than absolutely (capped_relative), s = atol + rtol·min(1, max(|y|, |y_new|)); a capped-relative
/// quadrature (R, whose period remainder is the result) is held apart from the RMS and tighter
/// (step_control.hpp, error_norm).
enum class StateScale { absolute, relative, capped_relative };

/// The Jacobian of a model, one per lane, and the solve of the stage matrix M = shift·I - J.
template <class J>
concept LaneJacobian = requires(J& jacobian, const J& factored, typename J::lane_type shift,
                                typename J::lane_type* r, std::size_t n,
                                LaneArena<typename J::lane_type>& arena) {
  typename J::lane_type;
  { J::storage_size(n) } -> std::convertible_to<std::size_t>;
  requires std::constructible_from < J, std::size_t, LaneArena<typename J::lane_type>
  & > ;
  jacobian.factor(shift);
  factored.solve(r);
};

/// A Jacobian that also reports the inertia of M after factor(): the lanes where M is positive
/// definite, i.e. no eigenvalue of J exceeds the shift (only a symmetric J can tell).
template <class J>
concept JacobianWithInertia = LaneJacobian<J> && requires(const J& factored) {
  { factored.positive_definite() } -> std::convertible_to<lane_mask<typename J::lane_type>>;
};

/// A model of lanes: y' = f(y, t) with quadratures q' = p(y, t), parameters per lane.
///   Parameters      one lane's parameters (plain doubles), given with set_lane()
///   Workspace       scratch over caller-owned storage (storage_size(n) values)
///   Jacobian        a LaneJacobian of f with respect to y
///   period          the drive period (periods are the unit of the schedule)
///   max_quadratures the most quadratures it can carry (the steppers size their storage for it)
///   quadrature_count()  the quadratures this instance carries (chosen at run time)
///   error_controlled(p) which of them steer the step
///   scale(k)        how component k's error is weighted
///   quadrature_scale(p)  how quadrature p's error is weighted, where it steers the step
///   evaluate        f and the quadrature integrands at (y, t)
///   linearize       evaluate() plus J, ∂f/∂t and the integrands' gradients
template <class M>
concept LaneModel = requires(const M& model, M& mutable_model, typename M::Workspace& work,
                             typename M::Jacobian& jacobian, const typename M::lane_type* y,
                             typename M::lane_type* out, typename M::lane_type t,
                             const typename M::Parameters& parameters, std::size_t k,
                             LaneArena<typename M::lane_type>& arena) {
  typename M::lane_type;
  typename M::Parameters;
  requires LaneJacobian<typename M::Jacobian>;
  { M::period } -> std::convertible_to<double>;
  { M::max_quadratures } -> std::convertible_to<std::size_t>;
  { model.quadrature_count() } -> std::same_as<std::size_t>;
  { model.error_controlled(k) } -> std::same_as<bool>;
  { M::Workspace::storage_size(k) } -> std::convertible_to<std::size_t>;
  requires std::constructible_from < typename M::Workspace, std::size_t, LaneArena<typename M::lane_type>
  & > ;
  { model.dimension() } -> std::same_as<std::size_t>;
  { model.scale(k) } -> std::same_as<StateScale>;
  { model.quadrature_scale(k) } -> std::same_as<StateScale>;
  mutable_model.set_lane(k, parameters);
  model.evaluate(work, y, t, out, out);
  model.linearize(work, y, t, out, out, jacobian, out, out, out);
};

/// A model that evaluates at a small displacement from the point of its last linearize() on the
/// same workspace more cheaply than at a new point: evaluate_displaced(work, y, δ, t, τ, f, qdot)
/// is evaluate() at (y + δ, t + τ), where (y, t) is that point (a Rosenbrock stage argument).
template <class M>
concept EvaluatesDisplaced = LaneModel<M> &&
    requires(const M& model, typename M::Workspace& work, const typename M::lane_type* y,
             typename M::lane_type* out, typename M::lane_type t) {
  model.evaluate_displaced(work, y, y, t, t, out, out);
};

/// A model that reports its row profile (docs/model.md §3 "Row profiles"): each row's share of the
/// drive integrand and the alignment of each link, links() of them.
template <class M>
concept ReportsRowProfile = LaneModel<M> &&
    requires(const M& model, typename M::Workspace& work, const typename M::lane_type* y,
             typename M::lane_type t, typename M::lane_type* out) {
  { model.links() } -> std::same_as<std::size_t>;
  model.row_profile(work, y, t, out, out);
};

}  // namespace rotorsweep::kernels
