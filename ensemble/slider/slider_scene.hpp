// A slider scene as data (docs/model.md §9): the experiment's rotor grid, substrate, drive and scan in SI
// units, and their scaled form (length a, energy μ0 m²/(4π a³), time a/(2π v)) that the kernel integrates.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "ensemble/engine/device.hpp"
#include "kernels/models/slider/infinite_substrate.hpp"
#include "kernels/models/slider/slider_model.hpp"
#include "kernels/models/slider/substrate_box_sums.hpp"
#include "kernels/models/slider/substrate_table.hpp"
#include "kernels/steppers/step_control.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

/// The slider's stepper and tolerance where a scene names none: on the experiment's scan rodas5p at
/// rtol 5e-7 has the friction within 2.5e-7 and the energy balance per period within 6e-7 in 2.2 s,
/// where the row model's default rodas4p2 at rtol 1e-6 leaves the balance at 1e-4 (docs/performance.md
/// "The slider").
inline constexpr std::string_view default_slider_stepper_name = "rodas5p";

/// How a member's stage systems are solved and its pair sums formed (numerics.linear_solver, docs/numerics.md
/// "The full array at any size"): a dense LDLᵀ of K beside direct pair sums (O(n³) per step, the inertia from
/// the pivots), conjugate gradients with K's products by lattice convolutions (O(n log n) per step and O(n)
/// memory, an inertia bound), or by size (automatic: krylov from `krylov_from_rotors` rotors on the CPU).
enum class SliderSolver { dense, krylov, automatic };

/// How a member's angles start: rows (along x, fixed y) alternately near 0 and π, all near 0, or
/// every angle uniform on [0, 2π) (the first two with uniform noise of full width `noise`), or
/// given angle by angle (SliderScene::given_angles).
enum class SliderStart { alternating_rows, aligned, random, given };

/// A slider's rotor grid.
struct SliderSize {
  std::size_t columns = 7;  ///< rotors along x, the sliding direction
  std::size_t rows = 7;     ///< rotors along y
  std::size_t rotors() const { return columns * rows; }
  bool operator==(const SliderSize&) const = default;
};

struct SliderScene {
  // [slider]
  std::vector<SliderSize> sizes{{7, 7}};  ///< one or more grids (a sweep axis)
  double spacing = 16e-3;                 ///< a, m (slider and substrate)
  double moment = 4.57e-2;                ///< m, A m²
  double inertia = 7.48e-10;              ///< I, kg m²
  std::vector<double> dampings{2.5e-6};   ///< γ, kg m²/s (a sweep axis)
  /// γ of the members being run (slider_variant picks it from dampings)
  double damping = 2.5e-6;
  bool overdamped = false;              ///< γ θ̇ = τ instead of I θ̈ = τ − γ θ̇
  double tilt = 0.0;                    ///< rad: the grid turned about z (kernels::SliderPlacement)
  double shift_x = 0.0, shift_y = 0.0;  ///< m: the grid shifted before it is turned

  // [substrate]
  std::size_t substrate_columns = 35;
  std::size_t substrate_rows = 35;
  /// substrate.extent = "infinite": a moment at every integer point of the plane (its field by the Fourier
  /// series of kernels::InfiniteSubstrate), no edges; columns and rows then have no meaning.
  bool substrate_infinite = false;
  double substrate_moment = 5.03e-2;  ///< m_sub, A m²
  double substrate_angle = 0.0;       ///< φ, rad: moments (cos φ, 0, −sin φ)
  double nodes_per_depth = 16.0;      ///< table nodes per separation h along x (error ∝ (h / nodes)⁶)

  // [drive]
  std::vector<double> speeds{8e-3};  ///< v, m/s (a sweep axis)
  double rest = 0.5;                 ///< s at rest before sliding, at every speed
  /// Whole substrate periods slid after the rest at every speed (drive.periods); 0: the run ends at
  /// `end` s instead (one speed only).
  std::size_t periods = 0;
  /// v and the end of the run (s) of the members being run: slider_variant picks v from speeds and
  /// sets end = rest + periods a/v where periods is given.
  double speed = 8e-3;
  double end = 10.5;
  /// Whole periods of sliding before the friction and the order parameters are averaged
  /// (drive.relax_periods: the transient after the rest, as a row member's relax periods); unset, 1, or
  /// none where the run slides one period only (averaging_start).
  std::optional<std::size_t> relax_periods;
  /// The first averaged period of a run that slides `sliding` ≥ 1 whole periods.
  std::size_t averaging_start(std::size_t sliding) const {
    return relax_periods ? *relax_periods : std::min<std::size_t>(1, sliding - 1);
  }

  // [sweep]
  std::vector<double> separations{8e-3};  ///< h, m

  // [initial]
  SliderStart start = SliderStart::alternating_rows;
  double noise = 3.141592653589793 / 24.0;  ///< full width of the uniform noise, rad
  std::size_t replicas = 1;
  std::uint64_t seed = 1;
  /// With SliderStart::given: angle of rotor (row r, column c) at [r · columns + c], r = 0 the row
  /// with the smallest y, c = 0 the column with the smallest x (one size).
  std::vector<double> given_angles;

  // [observables]
  std::size_t samples_per_period = 50;  ///< time series resolution (a period is a / v)
  bool series = true;                   ///< store the time series (friction, order parameters, energy)
  bool angles = false;                  ///< store every rotor's angle at every sample
  bool energies = false;                ///< the substrate and pair energies apart, per sample
  bool field = false;                   ///< the mean substrate field over the rotors' sites, per sample
  bool sublattices = false;             ///< even and odd rows' mean moment and substrate torque, per sample
  bool torques = false;                 ///< every rotor's substrate torque at every sample
  bool forces = false;                  ///< the substrate's force on the slider, F_x, F_y, F_z, per sample
  /// Whether samples need the substrate's field and torques rotor by rotor.
  bool rotor_observables() const { return energies || field || sublattices || torques; }
  /// The series beyond friction, order parameters and energy (observables.<key>), each with whether
  /// the scene asks for it.
  std::array<std::pair<const char*, bool>, 6> optional_series() const {
    return {{{"angles", angles},
             {"energies", energies},
             {"field", field},
             {"sublattices", sublattices},
             {"torques", torques},
             {"forces", forces}}};
  }

  // [numerics]
  kernels::StepperId stepper = *kernels::parse_stepper(default_slider_stepper_name);
  double rtol = 5e-7;
  double atol = 5e-7;
  double max_steps = 1e8;
  /// Where the members run: CPU lanes, or a CUDA GPU, a member per team of threads (ensemble/slider/
  /// slider_team_member.hpp; the slider's default stepper only).
  Device device = Device::cpu;
  SliderSolver linear_solver = SliderSolver::automatic;
  /// numerics.global_error = "shadow": every member runs again at tolerances × shadow_tolerance_scale
  /// and friction_error is the difference's Richardson estimate (ensemble/slider/slider_shadow.hpp);
  /// "local": no shadow runs and no friction error
  bool shadow_runs = true;

  std::string output_path = "results/slider.h5";
  std::string text;  ///< the scene file as read

  std::size_t member_count() const {
    return sizes.size() * speeds.size() * dampings.size() * separations.size() * replicas;
  }
};

/// Sizes from which numerics.linear_solver = "auto" takes conjugate gradients (docs/performance.md "The full
/// array at any size": below it the dense LDLᵀ on SIMD lanes is faster per member).
inline constexpr std::size_t krylov_from_rotors = 196;
/// Whether members of `size` run matrix-free (conjugate gradients, pair sums by FFT) rather than dense.
bool matrix_free(const SliderScene& scene, SliderSize size);

/// The scene as its members of speeds[speed] and dampings[damping] run it: speed, damping and end set.
SliderScene slider_variant(const SliderScene& scene, std::size_t speed, std::size_t damping);

/// The scene's units: energy E0 = μ0 m²/(4π a³) in J, time T0 = a/(2π v) in s, so that one substrate
/// period a/v is 2π; forces in E0/a, power in E0/T0.
struct SliderUnits {
  double energy, time, length, force, power;
  explicit SliderUnits(const SliderScene& scene);
};

/// The substrate lattice under a slider of `size`, centred, at separation h (m).
kernels::SubstrateLattice substrate_lattice(const SliderScene& scene, SliderSize size, double separation);

/// The slider's displacement at the end of the run, in units of a.
double final_displacement(const SliderScene& scene);

/// The scene's placement of the rotors over the substrate, in units of a.
kernels::SliderPlacement slider_placement(const SliderScene& scene);

/// How a table's nodes get the substrate's field: the direct sum over every moment (what the experiment's
/// 7 × 7 scan takes, its bits), box sums over summed-area tables (the same finite lattice exactly, to
/// rounding, in a fraction of the work once tracks × nodes × moments passes `direct_sum_terms`; unturned
/// sliders), or the infinite lattice's Fourier series.
enum class SubstrateSums { direct, box, infinite };
/// Above this many dipole terms (tracks × nodes × moments, about a second of direct sums) a finite
/// substrate's table comes from box sums.
inline constexpr double direct_sum_terms = 1e8;

/// Where the table of the substrate field lies for a slider of `size` at separation h (m): the
/// lattice, the tracks (y of each row, or of each rotor of a turned slider) and the span along x (units
/// of a) of the whole path, with half a lattice constant beyond both ends so that no step's stage leaves
/// it, the node spacing (at most h / nodes_per_depth; with box sums or an infinite lattice a whole
/// fraction 1/per_period of a) and how the nodes are summed; with dy, ddepth its tracks moved along y and
/// the substrate farther by ddepth.
struct SubstrateTableLayout {
  kernels::SubstrateLattice lattice;
  std::vector<double> tracks;
  double x_begin = 0, x_end = 0, dx = 1, tilt = 0;
  SubstrateSums sums = SubstrateSums::direct;
  std::size_t per_period = 0;  ///< nodes per lattice constant (box sums, infinite)
  /// Whether one track serves every track: an infinite lattice under an unturned slider.
  bool shared_track() const { return sums == SubstrateSums::infinite && tilt == 0.0; }
  /// The table's intervals.
  std::size_t intervals() const {
    if (sums == SubstrateSums::direct) return kernels::SubstrateTable::intervals_over(x_begin, x_end, dx);
    return std::size_t(std::ceil((x_end - x_begin) * double(per_period) - 1e-9));
  }
  /// Bytes of the table's coefficients (12 per stored track and interval) and of the nodes it is fitted to
  /// (box sums: every track's, and one phase's summed-area table).
  double bytes() const;
};
SubstrateTableLayout substrate_table_layout(const SliderScene& scene, SliderSize size, double separation,
                                            double dy = 0.0, double ddepth = 0.0);

/// The table of the substrate field over that layout: direct sums or box sums lane_width<V> nodes or
/// offsets at a time (the same table for every V), or the infinite lattice's series. `stopped()` is asked
/// between blocks of nodes: once it is true the build ends with kernels::SubstrateTableStopped.
template <class V>
kernels::SubstrateTable substrate_table(const SliderScene& scene, SliderSize size, double separation,
                                        double dy = 0.0, double ddepth = 0.0,
                                        const std::function<bool()>& stopped = {}) {
  const SubstrateTableLayout at = substrate_table_layout(scene, size, separation, dy, ddepth);
  if (at.sums == SubstrateSums::direct)
    return kernels::SubstrateTable(at.lattice, at.tracks, at.x_begin, at.x_end, at.dx, at.tilt,
                                   std::type_identity<V>{}, stopped);
  const std::size_t intervals = at.intervals(), m = at.per_period;
  const double step = 1.0 / double(m);
  if (at.sums == SubstrateSums::infinite) {
    const kernels::InfiniteSubstrate infinite(at.lattice.depth, at.lattice.angle, at.tilt,
                                              at.lattice.x_offset, at.lattice.y_offset);
    return kernels::SubstrateTable(
        at.tracks.size(), intervals, at.x_begin, step,
        [&](std::size_t track, std::vector<kernels::TableNode>& nodes) {
          if (stopped && stopped()) throw kernels::SubstrateTableStopped{};
          infinite.track_nodes(at.tracks[track], at.x_begin, m, nodes);
        },
        at.shared_track());
  }
  // box sums: the tracks of an unturned slider lie an integer apart, from its first row's
  const auto nodes = kernels::box_sum_nodes<V>(at.lattice, at.tracks.front(), at.tracks.size(), at.x_begin, m,
                                               intervals, stopped);
  return kernels::SubstrateTable(
      at.tracks.size(), intervals, at.x_begin, step,
      [&](std::size_t track, std::vector<kernels::TableNode>& out) { out = nodes[track]; });
}

/// The row model's substrate strength A at separation h (docs/model.md §9 "Mapping onto the row model"):
/// the paper's point-dipole estimate (a/h)³ m_sub/m ...
double paper_drive_amplitude(const SliderScene& scene, double separation);
/// ... and the first harmonic of the substrate field along the slider's middle row, μ B₁ with
/// B₁ = (|B_x,1| + |B_z,1|)/2 over one lattice period (64 points), in units of μ0 m²/(4π a³).
double field_drive_amplitude(const SliderScene& scene, SliderSize size, double separation);

/// One member's scaled parameters over `table` (a view of coefficients where the member reads them).
kernels::SliderParameters slider_parameters(const SliderScene& scene,
                                            const kernels::SubstrateTableView& table);

/// Where a member sits in the scene's plan: size-major, then speed, damping, separation, replica.
struct SliderMemberIndex {
  std::size_t size = 0, speed = 0, damping = 0, separation = 0, replica = 0;
};

/// The angles a member starts from: seed and (size, separation, replica) pick its stream, so a
/// member's start does not depend on the others in the scene.
std::vector<double> slider_start(const SliderScene& scene, SliderMemberIndex member);

}  // namespace rotorsweep::ensemble
