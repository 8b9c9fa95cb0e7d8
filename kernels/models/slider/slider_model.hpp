// The experiment's slider (docs/model.md §9): a grid of rotors coupled as point dipoles, sliding over a
// substrate lattice; I θ̈ = τ − γ θ̇ (or γ θ̇ = τ), friction force and dissipation as quadratures.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "kernels/lanes/angles.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/lane_math.hpp"
#include "kernels/linear/second_order_jacobian.hpp"
#include "kernels/models/slider/slider_pairs.hpp"
#include "kernels/models/slider/substrate_table.hpp"
#include "kernels/steppers/model_concept.hpp"

namespace rotorsweep::kernels {

/// Where the rotors sit over the substrate (units of a): rotor (i, j) at R(tilt)·(i + shift_x, j + shift_y)
/// + (ξ, 0), the grid shifted and then turned about z by `tilt` (its rows and the rotors' axes
/// together; the rotors turn in the plane of z and (cos tilt, sin tilt, 0)), sliding along x. The
/// substrate's field is read along tracks: the rows' y, or each rotor's own y when turned.
struct SliderPlacement {
  double tilt = 0.0, shift_x = 0.0, shift_y = 0.0;

  ROTORSWEEP_HD bool turned() const { return tilt != 0.0; }
  /// Rotor (i, j)'s x at ξ = 0 and the y of its path.
  ROTORSWEEP_HD double start_x(std::size_t i, std::size_t j) const {
    if (!turned()) return double(i) + shift_x;
    return std::cos(tilt) * (double(i) + shift_x) - std::sin(tilt) * (double(j) + shift_y);
  }
  ROTORSWEEP_HD double path_y(std::size_t i, std::size_t j) const {
    if (!turned()) return double(j) + shift_y;
    return std::sin(tilt) * (double(i) + shift_x) + std::cos(tilt) * (double(j) + shift_y);
  }
  /// The tracks of a grid: row j's y, or with a turned grid rotor r = j·columns + i's.
  std::vector<double> track_y(const SliderGrid& grid) const {
    std::vector<double> y;
    for (std::size_t j = 0; j < grid.rows; ++j)
      if (!turned())
        y.push_back(path_y(0, j));
      else
        for (std::size_t i = 0; i < grid.columns; ++i) y.push_back(path_y(i, j));
    return y;
  }
};

/// One lane's parameters, scaled (the same for every lane type and both dynamics).
struct SliderParameters {
  SubstrateTableView substrate;   ///< the field along each row at this lane's separation
  double moment_ratio = 1.1;      ///< μ = m_sub / m
  double inertia = 1e-4;          ///< I (ignored when overdamped)
  double damping = 0.1;           ///< γ
  double speed = 0.0;             ///< v, in a per unit time
  double rest = 0.0;              ///< t_rest, before which the slider stands still
  double stage_residual = 1e-10;  ///< a matrix-free stage solve's relative residual (SpectralStiffness)
};

/// Scaled units (docs/model.md §9): length a, energy μ0 m²/(4π a³), the substrate field in units of
/// μ0 m_sub/(4π a³) times μ = m_sub/m. Per rotor r:
///   E = Σ_{r<q} (P c_r c_q + Q s_r s_q) − μ Σ_r (B_x c_r − B_z s_r),  τ_r = −∂E/∂θ_r,
/// the slider at ξ(t) = v·max(0, t − t_rest), and the drive's force F = ∂E/∂ξ. Quadratures: drive
/// ∫F dt (its impulse; work = v ∫F dt) and stokes ∫γ Σ θ̇² dt (dissipation). Satisfies LaneModel.
/// `Pairs` sums the pair couplings and holds K: DirectPairs (O(n²) sums, K dense, LDLᵀ; device code too) or
/// SpectralPairs (kernels/models/slider/spectral_pairs.hpp: FFT, K without a matrix; host code).
template <class V, bool Inertial, class Pairs = DirectPairs<V>>
class SliderModel {
 public:
  using lane_type = V;
  using Jacobian = SecondOrderJacobian<V, Inertial, typename Pairs::Stiffness>;
  static constexpr double period = two_pi;  ///< a substrate period when v = 1/(2π)
  /// Two quadratures: the impulse (steers the step) and the dissipation.
  static constexpr std::size_t max_quadratures = 2;
  static constexpr std::size_t impulse_index = 0, dissipation_index = 1;
  ROTORSWEEP_HD static constexpr std::size_t quadrature_count() { return max_quadratures; }
  ROTORSWEEP_HD static constexpr bool error_controlled(std::size_t p) { return p == impulse_index; }

  using Parameters = SliderParameters;

  /// P and Q depend only on the offset between two rotors (Pairs tables them), and each rotor's start.
  static constexpr std::size_t storage_size(const SliderGrid& grid) {
    return Pairs::storage_size(grid) + grid.rotors();
  }

  struct Workspace {
    static constexpr std::size_t storage_size(std::size_t dimension) {
      return 10 * Jacobian::rotors(dimension);
    }
    ROTORSWEEP_HD Workspace(std::size_t dimension, LaneArena<V>& arena)
        : sin(arena.take(Jacobian::rotors(dimension))),
          cos(arena.take(Jacobian::rotors(dimension))),
          p_cos(arena.take(Jacobian::rotors(dimension))),
          q_sin(arena.take(Jacobian::rotors(dimension))),
          torque(arena.take(Jacobian::rotors(dimension))),
          bx(arena.take(Jacobian::rotors(dimension))),
          bz(arena.take(Jacobian::rotors(dimension))),
          dbx(arena.take(Jacobian::rotors(dimension))),
          dbz(arena.take(Jacobian::rotors(dimension))),
          curvature(arena.take(Jacobian::rotors(dimension))) {}
    V *sin, *cos;      // sin θ_r, cos θ_r
    V *p_cos, *q_sin;  // (P c)_r, (Q s)_r
    V* torque;         // τ_r
    V *bx, *bz;        // μ B at rotor r
    V *dbx, *dbz;      // μ ∂B/∂x
    V* curvature;      // μ (∂²B_x/∂x² c_r − ∂²B_z/∂x² s_r)
  };

  ROTORSWEEP_HD SliderModel(const SliderGrid& grid, const SliderPlacement& placement, LaneArena<V>& arena)
      : grid_(grid),
        n_(grid.rotors()),
        turned_(placement.turned()),
        pairs_(grid, arena),
        start_x_(arena.take(n_)) {
    if (arena.counting()) return;
    for (std::size_t r = 0; r < n_; ++r) start_x_[r] = V(placement.start_x(column(r), row(r)));
  }

  /// The integration loop's form (dimension, arena, arguments): the dimension follows from the grid.
  ROTORSWEEP_HD SliderModel(std::size_t, LaneArena<V>& arena, const SliderGrid& grid,
                            const SliderPlacement& placement)
      : SliderModel(grid, placement, arena) {}

  ROTORSWEEP_HD void set_lane(std::size_t lane, const Parameters& p) {
    substrate_[lane] = p.substrate;
    lane_set(mu_, lane, p.moment_ratio);
    lane_set(inertia_, lane, Inertial ? p.inertia : 0.0);
    lane_set(damping_, lane, p.damping);
    lane_set(inv_damping_, lane, 1.0 / p.damping);
    lane_set(inv_inertia_, lane, Inertial ? 1.0 / p.inertia : 0.0);
    lane_set(speed_, lane, p.speed);
    lane_set(rest_, lane, p.rest);
    lane_set(stage_residual_, lane, p.stage_residual);
  }

  ROTORSWEEP_HD const SliderGrid& grid() const { return grid_; }
  ROTORSWEEP_HD std::size_t rotors() const { return n_; }
  ROTORSWEEP_HD std::size_t dimension() const { return Inertial ? 2 * n_ : n_; }
  ROTORSWEEP_HD static constexpr StateScale scale(std::size_t) { return StateScale::absolute; }
  ROTORSWEEP_HD static constexpr StateScale quadrature_scale(std::size_t) { return StateScale::relative; }

  /// ξ(t), the slider's displacement.
  ROTORSWEEP_HD V displacement(V t) const { return speed_ * lane_max(V(0.0), t - rest_); }

  ROTORSWEEP_HD void evaluate(Workspace& w, const V* y, V t, V* f, V* qdot) const {
    prepare(w, y, t, false);
    rates(w, y, f, qdot);
  }

  ROTORSWEEP_HD void linearize(Workspace& w, const V* y, V t, V* f, V* qdot, Jacobian& J, V* df_dt, V* dq_dy,
                               V* dq_dt) const {
    prepare(w, y, t, true);
    rates(w, y, f, qdot);
    V time_sums[max_quadratures];
    jacobian_range(w, y, t, J, df_dt, dq_dy, time_sums, 0, n_);
    team_time_derivatives(time_sums, t, qdot, dq_dt);
  }

  // A team's evaluation (docs/architecture.md "Teams"): each rank takes its rotors' trigonometry and
  // field (prepare_range), then, once every rank's is in place (the pair sums read every rotor), their
  // pair sums and torques (torque_range), rates and rows of K. Each rotor's values come from the same
  // operations in the same order as over every rotor, so any split gives f, K, ∂f/∂t and the gradients
  // bit for bit; only the sums over rotors (the quadratures' integrands) take the team's order.

  /// Sums over rotors [begin, end): −Σ ∂E/∂ξ terms (the drive's force) and the dissipation's Σ θ̇² or Σ τ².
  struct RotorSums {
    V force = V(0.0), dissipation = V(0.0);
  };

  /// sin, cos and the substrate field of rotors [begin, end) at (y, t); with `curvatures` also the
  /// second x-derivative term of F.
  ROTORSWEEP_HD void prepare_range(Workspace& w, const V* y, V t, bool curvatures, std::size_t begin,
                                   std::size_t end) const {
    const V xi = displacement(t);
    for (std::size_t r = begin; r < end; ++r) {
      lane_sincos(y[r], w.sin[r], w.cos[r]);
      const TrackField<V> b =
          field_in_lanes(substrate_.data(), turned_ ? r : row(r), xi + start_x_[r], curvatures);
      w.bx[r] = mu_ * b.bx;
      w.bz[r] = mu_ * b.bz;
      w.dbx[r] = mu_ * b.dbx;
      w.dbz[r] = mu_ * b.dbz;
      if (curvatures) w.curvature[r] = mu_ * (b.d2bx * w.cos[r] - b.d2bz * w.sin[r]);
    }
  }
  /// P c, Q s and τ of rotors [begin, end), once every rank's prepare_range at the point is done (spectral
  /// pairs: every rotor at once).
  ROTORSWEEP_HD void torque_range(Workspace& w, std::size_t begin, std::size_t end) const {
    pairs_.sums(w.cos, w.sin, w.p_cos, w.q_sin, begin, end);
    for (std::size_t r = begin; r < end; ++r)
      w.torque[r] = w.sin[r] * w.p_cos[r] - w.cos[r] * w.q_sin[r] - (w.bx[r] * w.sin[r] + w.bz[r] * w.cos[r]);
  }
  /// f of rotors [begin, end) (θ̇, and θ̈ with inertia) after their torque_range, and their sums.
  ROTORSWEEP_HD RotorSums rates_range(const Workspace& w, const V* y, V* f, std::size_t begin,
                                      std::size_t end) const {
    RotorSums sums;
    sums.force = force_range(w, begin, end);
    for (std::size_t r = begin; r < end; ++r) {
      if constexpr (Inertial) {
        f[r] = y[n_ + r];
        f[n_ + r] = (w.torque[r] - damping_ * y[n_ + r]) * inv_inertia_;
        sums.dissipation += y[n_ + r] * y[n_ + r];
      } else {
        f[r] = w.torque[r] * inv_damping_;
        sums.dissipation += w.torque[r] * w.torque[r];
      }
    }
    return sums;
  }
  /// The quadratures' integrands from the sums over every rotor.
  ROTORSWEEP_HD void team_integrands(const RotorSums& sums, V* qdot) const {
    qdot[impulse_index] = sums.force;
    qdot[dissipation_index] = Inertial ? damping_ * sums.dissipation : sums.dissipation * inv_damping_;
  }
  /// K's rows [begin, end) (every column), J's dynamics, ∂f/∂t and the quadratures' gradients dq_dy of
  /// rotors [begin, end) at time t, after their rates_range at the point (with curvatures), and their
  /// parts of the sums behind ∂q̇/∂t in time_sums (−Σ curvature, Σ τ ∂f/∂t; team_time_derivatives).
  /// `J` is SecondOrderJacobian or a team's (stiffness(), set_dynamics()).
  template <class Matrix>
  ROTORSWEEP_HD void jacobian_range(const Workspace& w, const V* y, V t, Matrix& J, V* df_dt, V* dq_dy,
                                    V* time_sums, std::size_t begin, std::size_t end) const {
    const std::size_t dim = dimension();
    auto& K = J.stiffness();
    J.set_dynamics(inertia_, damping_);
    // ∂/∂t = ξ'(t) ∂/∂ξ, ξ' = v once the slider moves
    const V rate = lane_select(t > rest_, speed_, V(0.0));
    const V weight = Inertial ? inv_inertia_ : inv_damping_;
    V force_rate(0.0), dissipation_rate(0.0);
    if constexpr (Pairs::matrix_free) {
      K.set_pairs(&pairs_.convolution());
      K.set_residual(stage_residual_);
    }
    for (std::size_t r = begin; r < end; ++r) {
      // K = ∂τ/∂θ = −∂²E/∂θ²: off the diagonal −(P s_r s_q + Q c_r c_q), formed from the pair's first rotor
      const V diagonal =
          w.cos[r] * w.p_cos[r] + w.sin[r] * w.q_sin[r] - (w.bx[r] * w.cos[r] - w.bz[r] * w.sin[r]);
      if constexpr (Pairs::matrix_free) {
        K.set_rotor(r, w.sin[r], w.cos[r], diagonal);
      } else {
        for (std::size_t k = 0; k < n_; ++k) {
          if (k == r) continue;
          const std::size_t first = k < r ? k : r, second = k < r ? r : k, at = pairs_.at(first, second);
          K.entry(r, k) = lane_neg(pairs_.p(at) * w.sin[first] * w.sin[second] +
                                   pairs_.q(at) * w.cos[first] * w.cos[second]);
        }
        K.entry(r, r) = diagonal;
      }
      const V torque_rate = lane_neg(rate) * (w.dbx[r] * w.sin[r] + w.dbz[r] * w.cos[r]);
      if constexpr (Inertial) df_dt[r] = V(0.0);
      df_dt[Inertial ? n_ + r : r] = weight * torque_rate;
      force_rate -= w.curvature[r];
      dq_dy[impulse_index * dim + r] = w.dbx[r] * w.sin[r] + w.dbz[r] * w.cos[r];
      if constexpr (Inertial) dq_dy[impulse_index * dim + n_ + r] = V(0.0);
    }
    V* grad = dq_dy + dissipation_index * dim;
    if constexpr (!Inertial && Pairs::matrix_free) K.multiply(w.torque, grad);  // (K τ)_k, every rotor
    for (std::size_t k = begin; k < end; ++k) {
      if constexpr (Inertial) {
        grad[k] = V(0.0);
        grad[n_ + k] = V(2.0) * damping_ * y[n_ + k];
      } else {
        // ∂(Σ τ²/γ)/∂θ_k = (2/γ) Σ_r τ_r K_rk (K_rk = K_kr, this rank's row k), and ∂/∂t = (2/γ) Σ_r τ_r
        // ∂τ_r/∂t
        V sum = grad[k];
        if constexpr (!Pairs::matrix_free) {
          sum = V(0.0);
          for (std::size_t r = 0; r < n_; ++r) sum += w.torque[r] * K.entry(k, r);
        }
        grad[k] = V(2.0) * inv_damping_ * sum;
        dissipation_rate += w.torque[k] * df_dt[k];
      }
    }
    time_sums[impulse_index] = force_rate;
    time_sums[dissipation_index] = dissipation_rate;
  }
  /// ∂q̇/∂t at time t from the time sums over every rotor (the integrands are not needed).
  ROTORSWEEP_HD void team_time_derivatives(const V* time_sums, V t, const V*, V* dq_dt) const {
    const V rate = lane_select(t > rest_, speed_, V(0.0));
    dq_dt[impulse_index] = rate * time_sums[impulse_index];
    dq_dt[dissipation_index] = Inertial ? V(0.0) : V(2.0) * time_sums[dissipation_index];
  }

  /// The shift δ (units of a) of the four tables that give the field's y- and z-derivatives to forces():
  /// tracks at y + δ and y − δ, and the substrate δ farther and δ nearer (a central difference: its
  /// error (δ/h)² ~ 1e-9, its rounding 1e-16/δ ~ 1e-11).
  static constexpr double gradient_step = 1e-5;
  enum GradientTable : std::size_t { y_plus, y_minus, z_plus, z_minus };
  /// Each gradient table's shift (along y, in depth; units of a), in GradientTable order.
  static constexpr std::array<std::array<double, 2>, 4> gradient_shifts{
      {{gradient_step, 0.0}, {-gradient_step, 0.0}, {0.0, gradient_step}, {0.0, -gradient_step}}};

  /// Lane `lane`'s four tables of the field at shifted tracks (GradientTable order), for forces().
  ROTORSWEEP_HD void set_gradient_tables(std::size_t lane, const std::array<SubstrateTableView, 4>& tables) {
    for (std::size_t g = 0; g < 4; ++g) gradient_[g][lane] = tables[g];
  }

  /// The substrate's force on the slider, F = Σ_r ∇(m_r·B)(p_r) in units of E0/a: F_x from the table's
  /// x-derivatives (−F, the drive's force), F_y and F_z by central differences of the gradient tables.
  ROTORSWEEP_HD void forces(Workspace& w, const V* y, V t, V& fx, V& fy, V& fz) const {
    prepare(w, y, t, false);
    fx = V(0.0);
    fy = V(0.0);
    fz = V(0.0);
    forces_range(w, t, 0, n_, fx, fy, fz);
  }
  /// Adds the force's parts from rotors [begin, end) at time t to fx, fy, fz, after their prepare_range.
  ROTORSWEEP_HD void forces_range(const Workspace& w, V t, std::size_t begin, std::size_t end, V& fx, V& fy,
                                  V& fz) const {
    const V xi = displacement(t), scale = mu_ * V(0.5 / gradient_step);
    for (std::size_t r = begin; r < end; ++r) {
      fx += field_work(w, r);
      const std::size_t track = turned_ ? r : row(r);
      const V x = xi + start_x_[r];
      const auto at = [&](GradientTable g) { return field_in_lanes(gradient_[g].data(), track, x); };
      const TrackField<V> yp = at(y_plus), ym = at(y_minus), zp = at(z_plus), zm = at(z_minus);
      fy += scale * ((yp.bx - ym.bx) * w.cos[r] - (yp.bz - ym.bz) * w.sin[r]);
      fz += scale * ((zp.bx - zm.bx) * w.cos[r] - (zp.bz - zm.bz) * w.sin[r]);
    }
  }

  /// E, the magnetic energy (pairs and substrate), in units of μ0 m²/(4π a³).
  ROTORSWEEP_HD V energy(Workspace& w, const V* y, V t) const {
    prepare(w, y, t, false);
    return energy_range(w, 0, n_);
  }

  /// ½ I Σ θ̇² (0 when overdamped).
  ROTORSWEEP_HD V kinetic_energy(const V* y) const { return kinetic_energy_of(velocity_squares(y, 0, n_)); }

  /// The alignment of neighbours along x and across y: the mean of cos(θ_r − θ_q) over neighbouring
  /// pairs in each direction (+1 ferromagnetic, −1 antiferromagnetic).
  ROTORSWEEP_HD void order_parameters(const V* y, V& along_x, V& across_y) const {
    along_x = V(0.0);
    across_y = V(0.0);
    alignment_range(y, 0, n_, along_x, across_y);
    mean_alignment(along_x, across_y);
  }

  // A sample's observables on a team: each rank's part of F (force_range), of E (energy_range, after
  // torque_range), of Σ θ̇² (velocity_squares) and of the alignments' sums (alignment_range), then the
  // team's sums.

  /// The magnetic energy of rotors [begin, end) (half of each pair's), after their torque_range.
  ROTORSWEEP_HD V energy_range(const Workspace& w, std::size_t begin, std::size_t end) const {
    V e(0.0);
    for (std::size_t r = begin; r < end; ++r)
      e += V(0.5) * (w.cos[r] * w.p_cos[r] + w.sin[r] * w.q_sin[r]) -
           (w.bx[r] * w.cos[r] - w.bz[r] * w.sin[r]);
    return e;
  }
  /// Σ θ̇² over rotors [begin, end) (0 when overdamped), and ½ I times such a sum.
  ROTORSWEEP_HD V velocity_squares(const V* y, std::size_t begin, std::size_t end) const {
    V e(0.0);
    if constexpr (Inertial)
      for (std::size_t r = begin; r < end; ++r) e += y[n_ + r] * y[n_ + r];
    return e;
  }
  ROTORSWEEP_HD V kinetic_energy_of(V velocity_squares) const { return V(0.5) * inertia_ * velocity_squares; }
  /// Adds cos(θ_r − θ_q) of the links from rotors [begin, end) to their neighbours at +x and +y.
  ROTORSWEEP_HD void alignment_range(const V* y, std::size_t begin, std::size_t end, V& along_x,
                                     V& across_y) const {
    V s, c;
    for (std::size_t r = begin; r < end; ++r) {
      if (column(r) + 1 < grid_.columns) {
        lane_sincos(y[r] - y[r + 1], s, c);
        along_x += c;
      }
      if (row(r) + 1 < grid_.rows) {
        lane_sincos(y[r] - y[r + grid_.columns], s, c);
        across_y += c;
      }
    }
  }
  /// The alignments' sums over every link into their means (1 where a direction has no link).
  ROTORSWEEP_HD void mean_alignment(V& along_x, V& across_y) const {
    const std::size_t x_links = (grid_.columns - 1) * grid_.rows, y_links = grid_.columns * (grid_.rows - 1);
    along_x = x_links ? along_x * V(1.0 / double(x_links)) : V(1.0);
    across_y = y_links ? across_y * V(1.0 / double(y_links)) : V(1.0);
  }
  /// The part of rotor r in −F, the drive's force (∂(m_r·B)/∂x), after its prepare_range.
  ROTORSWEEP_HD V field_work(const Workspace& w, std::size_t r) const {
    return w.dbx[r] * w.cos[r] - w.dbz[r] * w.sin[r];
  }
  /// A sample's sums over rotors for the rotor observables: the substrate energy −Σ μB·m, the pairs'
  /// ½ Σ (c P c + s Q s), Σ μB_∥ and Σ μB_z, and per row parity ([0]: rows j = 0, 2, …) Σ cos θ,
  /// Σ −sin θ and the substrate torques Σ −μ(B_∥ sin θ + B_z cos θ).
  struct RotorObservables {
    V substrate = V(0.0), pairs = V(0.0), field_axis = V(0.0), field_z = V(0.0);
    V moment_axis[2] = {V(0.0), V(0.0)}, moment_z[2] = {V(0.0), V(0.0)}, torque[2] = {V(0.0), V(0.0)};
  };
  /// Adds rotors [begin, end) to `sums`, after their torque_range; each one's substrate torque into
  /// torques[r] where given.
  ROTORSWEEP_HD void rotor_observables_range(const Workspace& w, std::size_t begin, std::size_t end,
                                             RotorObservables& sums, V* torques) const {
    for (std::size_t r = begin; r < end; ++r) {
      const V c = w.cos[r], s = w.sin[r], bx = w.bx[r], bz = w.bz[r];
      const V tau = lane_neg(bx * s + bz * c);  // the substrate's part of τ_r
      sums.substrate -= bx * c - bz * s;
      sums.pairs += V(0.5) * (c * w.p_cos[r] + s * w.q_sin[r]);
      sums.field_axis += bx;
      sums.field_z += bz;
      const std::size_t parity = row(r) % 2;
      sums.moment_axis[parity] += c;
      sums.moment_z[parity] -= s;
      sums.torque[parity] += tau;
      if (torques) torques[r] = tau;
    }
  }
  /// The drive's force from rotors [begin, end), after their prepare_range.
  ROTORSWEEP_HD V force_range(const Workspace& w, std::size_t begin, std::size_t end) const {
    V force(0.0);
    for (std::size_t r = begin; r < end; ++r) force -= field_work(w, r);
    return force;
  }

 private:
  ROTORSWEEP_HD std::size_t column(std::size_t r) const { return r % grid_.columns; }
  ROTORSWEEP_HD std::size_t row(std::size_t r) const { return r / grid_.columns; }

  /// f and the quadrature integrands from a prepared workspace.
  ROTORSWEEP_HD void rates(const Workspace& w, const V* y, V* f, V* qdot) const {
    team_integrands(rates_range(w, y, f, 0, n_), qdot);
  }

  /// sin, cos, the substrate field at every rotor, P c, Q s and τ; with `curvatures` also the
  /// second x-derivative term of F.
  ROTORSWEEP_HD void prepare(Workspace& w, const V* y, V t, bool curvatures) const {
    prepare_range(w, y, t, curvatures, 0, n_);
    torque_range(w, 0, n_);
  }

  SliderGrid grid_;
  std::size_t n_;
  bool turned_;  ///< a track per rotor (SliderPlacement::turned), else one per row
  Pairs pairs_;  ///< P and Q per offset (dy + rows − 1, dx + columns − 1), the same in every lane
  V* start_x_;   ///< each rotor's x at ξ = 0 (SliderPlacement::start_x), the same in every lane
  std::array<SubstrateTableView, lane_width<V>> substrate_{};
  std::array<std::array<SubstrateTableView, lane_width<V>>, 4> gradient_{};  ///< for forces() only
  V mu_ = V(1.0), inertia_ = V(1.0), inv_inertia_ = V(1.0), damping_ = V(1.0), inv_damping_ = V(1.0);
  V speed_ = V(0.0), rest_ = V(0.0), stage_residual_ = V(1e-10);
};

}  // namespace rotorsweep::kernels
