// What a slider member's samples and period boundaries become on the host, whichever backend ran it
// (docs/model.md §9 "Observables"): the series in SI, friction and energy balance per period, means.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "ensemble/slider/slider_sample_grid.hpp"
#include "ensemble/slider/slider_scene.hpp"
#include "ensemble/slider/slider_sweep.hpp"

namespace rotorsweep::ensemble {

/// A sample's observables, scaled: the drive's force F (the impulse's integrand), the order parameters
/// along x and across y, and the energy E + ½ I Σ θ̇².
struct SliderSample {
  double force = 0.0, order_x = 0.0, order_y = 0.0, energy = 0.0;
};

/// A sample's sums over rotors for SliderScene::energies, field and sublattices, scaled, as
/// SliderModel::RotorObservables gives them (energies in E0, μB in units of μ0 m_sub/(4π a³) times
/// m_sub/m; [0] the even rows j = 0, 2, …, [1] the odd rows).
struct SliderRotorSums {
  double substrate = 0.0, pairs = 0.0, field_axis = 0.0, field_z = 0.0;
  std::array<double, 2> moment_axis{}, moment_z{}, torque{};
};

/// Sizes m's series to `samples` samples: the four every scan keeps and those the scene asks for
/// (angles and torques: samples × rotors).
void size_slider_series(SliderMember& m, const SliderScene& scene, std::size_t samples);

/// Writes sample k of m's friction, order-parameter and energy series, in SI.
void record_slider_sample(SliderMember& m, std::size_t k, const SliderSample& sample,
                          const SliderUnits& units);

/// Writes sample k of the series the scene asks for among energies, field and sublattices, in SI: the
/// substrate and pairs' energies (J), the mean B_∥ and B_z (T), and each parity's mean moment and mean
/// substrate torque (N m; NaN for a parity without rows).
void record_slider_rotor_sums(SliderMember& m, std::size_t k, const SliderRotorSums& sums,
                              const SliderScene& scene);

/// Writes sample k of the force series from F (scaled, E0/a), in N.
void record_slider_forces(SliderMember& m, std::size_t k, const std::array<double, 3>& force,
                          const SliderUnits& units);

/// A member's impulse, dissipation and energy (scaled) at each period boundary of its grid.
struct SliderBoundaries {
  std::vector<double> impulse, dissipation, energy;
};

/// Fills m's friction, work, dissipation, stored energy and balance per period, its mean friction and
/// order parameters over the periods after SliderScene::averaging_start (the transient left out), and (with SliderScene::forces) the per-period means of F_y and F_z, from its
/// series (on `grid`'s samples) and boundaries; NaN where the member failed (`ok` false: its values
/// would describe a frozen state).
void summarize_slider_member(const SliderScene& scene, const SliderSampleGrid& grid,
                             const SliderBoundaries& at, bool ok, SliderMember& m);

/// Puts NaN before the member's own samples so that its series fill the timeline's `samples` columns
/// (a speed whose rest has fewer samples than the fastest one's).
void pad_to_timeline(SliderMember& m, std::size_t samples);

}  // namespace rotorsweep::ensemble
