// Test support: one rotor array (a scalar member) set up with FM/AFM initial conditions
// (docs/model.md §2) and run through the sweep driver, returning its period means.
#pragma once

#include <cstddef>
#include <vector>

#include "ensemble/rows/initial_conditions.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/scene.hpp"
#include "ensemble/rows/sweep.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::testing {

enum class Start { fm, afm };

/// FM or AFM angles with noise η_j ~ U[-noise, noise], member `member` of seed 7.
inline std::vector<double> initial_angles(std::size_t rows, Start start, double noise = 0.01,
                                          unsigned member = 0) {
  const ensemble::InitialCondition ic{
      start == Start::afm ? ensemble::InitialKind::afm : ensemble::InitialKind::fm, noise, 0.0, {}};
  return ensemble::initial_angles(ic, rows, 7, member);
}

/// One member (stream 0 of seed 7) of the row model on the scalar lane with the W, S, R
/// estimators, averaged over `average` periods after `relax`; the stepper by name.
inline ensemble::MemberResult run_member(std::size_t rows, double A, double g, Start start, int relax,
                                         int average, double rtol, double atol,
                                         const char* stepper = "rodas4") {
  ensemble::Scene scene;
  scene.row_counts = {rows};
  scene.rtol_values = {rtol};
  scene.atol_values = {atol};
  scene.g_values = {g};
  scene.A_values = {A};
  scene.seed = 7;
  scene.relax_periods = relax;
  scene.average_periods = average;
  scene.observables = {};
  scene.observables.set(ensemble::Observable::dissipation, true);
  scene.observables.set(ensemble::Observable::estimators, true);
  scene.stepper = *kernels::parse_stepper(stepper);
  scene.lanes = ensemble::LaneKind::scalar;
  const auto kind = start == Start::afm ? ensemble::InitialKind::afm : ensemble::InitialKind::fm;
  ensemble::Member member;
  member.A = A;
  member.g = g;
  member.kind = kind;
  member.rows = rows;
  member.rtol = rtol;
  member.atol = atol;
  const std::vector<ensemble::Member> members{member};
  return ensemble::run_sweep(scene, members, {.threads = 1}).results.front();
}

}  // namespace rotorsweep::testing
