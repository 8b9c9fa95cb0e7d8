// The slider scene's units, substrate, field tables, scaled parameters and starting angles
// (docs/model.md §9 "Scaled form" and "Initial conditions").
#include "ensemble/slider/slider_scene.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

#include "kernels/lanes/angles.hpp"
#include "kernels/lanes/counter_random.hpp"
#include "kernels/models/slider/infinite_substrate.hpp"

namespace rotorsweep::ensemble {

namespace {
constexpr double mu0_over_4pi = 1e-7;  // T m / A
}

SliderUnits::SliderUnits(const SliderScene& scene)
    : energy(mu0_over_4pi * scene.moment * scene.moment / std::pow(scene.spacing, 3)),
      time(scene.spacing / (kernels::two_pi * scene.speed)),
      length(scene.spacing),
      force(energy / scene.spacing),
      power(energy / time) {}

bool matrix_free(const SliderScene& scene, SliderSize size) {
  if (scene.linear_solver == SliderSolver::automatic)
    return scene.device == Device::cpu && size.rotors() >= krylov_from_rotors;
  return scene.linear_solver == SliderSolver::krylov;
}

SliderScene slider_variant(const SliderScene& scene, std::size_t speed, std::size_t damping) {
  SliderScene variant = scene;
  variant.speed = scene.speeds[speed];
  variant.damping = scene.dampings[damping];
  if (scene.periods > 0) variant.end = scene.rest + double(scene.periods) * scene.spacing / variant.speed;
  return variant;
}

kernels::SubstrateLattice substrate_lattice(const SliderScene& scene, SliderSize size, double separation) {
  const auto centre_offset = [](std::size_t slider, std::size_t substrate) {
    return 0.5 * double(slider - 1) - 0.5 * double(substrate - 1);
  };
  // an infinite lattice has a moment under every rotor of an unshifted slider at rest, as 5N × 5N has
  if (scene.substrate_infinite) return {0, 0, 0.0, 0.0, separation / scene.spacing, scene.substrate_angle};
  return {scene.substrate_columns,
          scene.substrate_rows,
          centre_offset(size.columns, scene.substrate_columns),
          centre_offset(size.rows, scene.substrate_rows),
          separation / scene.spacing,
          scene.substrate_angle};
}

kernels::SliderPlacement slider_placement(const SliderScene& scene) {
  return {scene.tilt, scene.shift_x / scene.spacing, scene.shift_y / scene.spacing};
}

double final_displacement(const SliderScene& scene) {
  return std::max(0.0, scene.end - scene.rest) * scene.speed / scene.spacing;
}

SubstrateTableLayout substrate_table_layout(const SliderScene& scene, SliderSize size, double separation,
                                            double dy, double ddepth) {
  const kernels::SliderPlacement placement = slider_placement(scene);
  const kernels::SliderGrid grid{size.columns, size.rows};
  double first = placement.start_x(0, 0), last = first;
  for (std::size_t j = 0; j < size.rows; ++j)
    for (std::size_t i = 0; i < size.columns; ++i) {
      first = std::min(first, placement.start_x(i, j));
      last = std::max(last, placement.start_x(i, j));
    }
  SubstrateTableLayout at{substrate_lattice(scene, size, separation),
                          placement.track_y(grid),
                          first - 0.5,
                          last + final_displacement(scene) + 0.5,
                          separation / scene.spacing / scene.nodes_per_depth,
                          placement.tilt};
  at.lattice.depth += ddepth;
  for (double& y : at.tracks) y += dy;
  const double terms = double(at.tracks.size()) * double(at.intervals() + 1) *
                       double(scene.substrate_columns) * double(scene.substrate_rows);
  if (scene.substrate_infinite)
    at.sums = SubstrateSums::infinite;
  else if (!placement.turned() && terms > direct_sum_terms)
    at.sums = SubstrateSums::box;
  if (at.sums != SubstrateSums::direct) at.per_period = std::size_t(std::ceil(1.0 / at.dx - 1e-9));
  return at;
}

double SubstrateTableLayout::bytes() const {
  const double nodes = double(intervals() + 1);
  const double stored = shared_track() ? 1.0 : double(tracks.size());
  double working = nodes * 9 * sizeof(double);  // one track's nodes
  if (sums == SubstrateSums::box)               // every track's nodes, and a phase's running and column sums
    working = stored * nodes * 6 * sizeof(double) + (nodes / double(per_period) + double(lattice.columns)) *
                                                        (2 * double(tracks.size()) + 2) * 6 * sizeof(double);
  return (nodes - 1) * stored * 12 * sizeof(double) + working;
}

double paper_drive_amplitude(const SliderScene& scene, double separation) {
  return std::pow(scene.spacing / separation, 3) * scene.substrate_moment / scene.moment;
}

double field_drive_amplitude(const SliderScene& scene, SliderSize size, double separation) {
  const auto lattice = substrate_lattice(scene, size, separation);
  const auto placement = slider_placement(scene);
  const kernels::InfiniteSubstrate infinite(lattice.depth, lattice.angle, 0.0, lattice.x_offset,
                                            lattice.y_offset);
  const std::size_t i = size.columns / 2, j = size.rows / 2;  // the centre rotor's path
  const double row = placement.path_y(i, j), column = placement.start_x(i, j);
  constexpr int points = 64;
  std::complex<double> bx(0.0), bz(0.0);  // Σ B e^{iφ}: the harmonic's amplitude whatever its phase
  for (int k = 0; k < points; ++k) {
    const double phase = kernels::two_pi * double(k) / points;
    const auto field =
        scene.substrate_infinite
            ? infinite.field_at(column + double(k) / points, row)
            : kernels::substrate_field(lattice, column + double(k) / points, row, placement.turned());
    // B_∥ along the rotors' in-plane axis (B_x unless the slider is turned)
    const double along = placement.turned() ? std::cos(placement.tilt) * field.x.value +
                                                  std::sin(placement.tilt) * field.y.value
                                            : field.x.value;
    bx += along * std::polar(1.0, phase);
    bz += field.z.value * std::polar(1.0, phase);
  }
  return scene.substrate_moment / scene.moment * (std::abs(bx) + std::abs(bz)) / points;
}

kernels::SliderParameters slider_parameters(const SliderScene& scene,
                                            const kernels::SubstrateTableView& table) {
  const SliderUnits units(scene);
  kernels::SliderParameters p;
  p.substrate = table;
  p.moment_ratio = scene.substrate_moment / scene.moment;
  p.inertia = scene.inertia / (units.energy * units.time * units.time);
  p.damping = scene.damping / (units.energy * units.time);
  p.speed = 1.0 / kernels::two_pi;
  p.rest = scene.rest / units.time;
  // far below the step's tolerance: a stage's error of ε relative moves the friction by about 4ε
  // (docs/numerics.md "The stage solve without a matrix")
  p.stage_residual = 1e-3 * scene.rtol;
  return p;
}

std::vector<double> slider_start(const SliderScene& scene, SliderMemberIndex member) {
  if (scene.start == SliderStart::given) return scene.given_angles;
  // keyed by the replica alone, as the row sweeps' draws: a member keeps its start whatever the
  // other axes hold (sizes share the first draws, rotor by rotor)
  const kernels::RandomStream stream(scene.seed, member.replica);
  const SliderSize size = scene.sizes[member.size];
  const std::size_t n = size.rotors();
  std::vector<double> theta(n);
  for (std::size_t r = 0; r < n; ++r) {
    const double u = stream.draw(r);
    switch (scene.start) {
      case SliderStart::alternating_rows:
        theta[r] = ((r / size.columns) % 2 ? 3.141592653589793 : 0.0) + scene.noise * (u - 0.5);
        break;
      case SliderStart::aligned: theta[r] = scene.noise * (u - 0.5); break;
      case SliderStart::random: theta[r] = kernels::two_pi * u; break;
      case SliderStart::given: break;
    }
  }
  return theta;
}

}  // namespace rotorsweep::ensemble
