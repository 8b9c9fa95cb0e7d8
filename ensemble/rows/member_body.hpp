// What a device member's body gives run_member (ensemble/rows/member_loop.hpp): its rows and integrator
// on one thread, a team or a warp's registers, as a concept the compiler checks against each form.
#pragma once

#include <concepts>
#include <cstddef>

#include "ensemble/rows/member_slots.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/steppers/lane_status.hpp"

namespace rotorsweep::ensemble {

/// The rows' turn over an accepted step: max_j |Δθ_j| and, where slip energies are on, Σ_j Δθ_j² (from
/// 0 in row order on one thread; a team's or a warp's sums of its threads' parts).
struct SlipTurns {
  double largest = 0.0, squares = 0.0;
};

/// A callable the concept hands to one() (a body runs it on one of its threads).
struct OnOneThread {
  ROTORSWEEP_HD void operator()() const {}
};

/// A member's body, started at its slot: static stochastic and period; attempt() → whether the step was
/// accepted; t(), t_stop(), status(); quadrature(p) (p: an index of the schedule's quadratures), drive()
/// (R(t)), alignment_integrand() (ρ̄ at the last attempt's start); keep_before(); turns(squares);
/// slip_rate(s, g) (the slip counter's rate at g); write_rows(out) (θ_j into out[j]); one(f) (f on one of
/// its threads); next_period(wrap); steps_accepted(), steps_rejected(); and the row profile's
/// profile_start(), profile_before(), profile_after(accepted), profile_take(out).
template <class B>
concept MemberBody = requires(B& body, const B& constant, const SlotSchedule& s, std::size_t p, double* out,
                              OnOneThread f) {
  { B::stochastic } -> std::convertible_to<bool>;
  { B::period } -> std::convertible_to<double>;
  { body.attempt() } -> std::convertible_to<bool>;
  { constant.t() } -> std::convertible_to<double>;
  { constant.t_stop() } -> std::convertible_to<double>;
  { constant.status() } -> std::same_as<kernels::LaneStatus>;
  { constant.quadrature(p) } -> std::convertible_to<double>;
  { constant.drive() } -> std::convertible_to<double>;
  { constant.alignment_integrand() } -> std::convertible_to<double>;
  body.keep_before();
  { constant.turns(true) } -> std::same_as<SlipTurns>;
  { constant.slip_rate(s, 1.0) } -> std::convertible_to<double>;
  constant.write_rows(out);
  body.one(f);
  body.next_period(true);
  { constant.steps_accepted() } -> std::convertible_to<double>;
  { constant.steps_rejected() } -> std::convertible_to<double>;
  body.profile_start();
  body.profile_before();
  body.profile_after(true);
  body.profile_take(out);
};

}  // namespace rotorsweep::ensemble
