// The slider model (kernels/models/slider/slider_model.hpp, docs/model.md §9): torques and the drive's force
// against differences of the energy (also for a shifted, turned slider over turned substrate moments), the
// linearization against differences of f, a 2 × 1 slider against a direct dense-sum reference, energy
// conservation and the energy balance, the overdamped limit, SIMD = scalar, and the range forms a team
// uses against the whole slider.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "kernels/lanes/team.hpp"
#include "kernels/models/slider/slider_model.hpp"
#include "kernels/models/slider/slider_on_teams.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/rosenbrock.hpp"
#include "kernels/steppers/team_integrator.hpp"
#include "kernels/steppers/team_rosenbrock.hpp"
#include "support/kernel_scratch.hpp"
#include "support/linearization_check.hpp"
#include "support/slider_fixture.hpp"

using namespace rotorsweep::kernels;
using rotorsweep::testing::scratch;
using namespace rotorsweep::testing::slider_fixture;

namespace {

using Inertial = SliderModel<double, true>;
using Overdamped = SliderModel<double, false>;

/// E and f at (y, t) of a model.
template <class Model>
double energy_of(const Model& m, const std::vector<double>& y, double t) {
  auto w = rotorsweep::testing::workspace(m);
  return m.energy(w, y.data(), t);
}

/// The energy of a slider by plain dipole sums of 3-vectors: every slider pair and every slider–substrate
/// pair, (m1·m2 − 3 (m1·r̂)(m2·r̂))/r³ in units of μ0 m²/(4π a³); rotor (i, j) at R(τ)(i + s_x, j + s_y)
/// + (ξ, 0) with moment (cos θ cos τ, cos θ sin τ, −sin θ), the substrate moments μ (cos φ, 0, −sin φ).
double dense_sum_energy(SliderGrid grid, const SubstrateLattice& lattice, const std::vector<double>& theta,
                        double xi, const SliderPlacement& placement = {}) {
  using Vec = std::array<double, 3>;
  const auto pair = [](const Vec& m1, const Vec& m2, const Vec& r) {
    const double d = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    const double m1r = (m1[0] * r[0] + m1[1] * r[1] + m1[2] * r[2]) / d;
    const double m2r = (m2[0] * r[0] + m2[1] * r[1] + m2[2] * r[2]) / d;
    return (m1[0] * m2[0] + m1[1] * m2[1] + m1[2] * m2[2] - 3.0 * m1r * m2r) / (d * d * d);
  };
  const std::size_t n = grid.rotors();
  const double c = std::cos(placement.tilt), s = std::sin(placement.tilt);
  const auto position = [&](std::size_t r) {
    const double x = double(r % grid.columns) + placement.shift_x,
                 y = double(r / grid.columns) + placement.shift_y;
    return Vec{c * x - s * y + xi, s * x + c * y, 0.0};
  };
  const auto moment = [&](std::size_t r) {
    return Vec{std::cos(theta[r]) * c, std::cos(theta[r]) * s, -std::sin(theta[r])};
  };
  const Vec substrate_moment{moment_ratio * std::cos(lattice.angle), 0.0,
                             -moment_ratio * std::sin(lattice.angle)};
  double e = 0.0;
  for (std::size_t r = 0; r < n; ++r) {
    for (std::size_t q = r + 1; q < n; ++q) {
      const Vec a = position(r), b = position(q);
      e += pair(moment(r), moment(q), {b[0] - a[0], b[1] - a[1], b[2] - a[2]});
    }
    for (std::size_t k = 0; k < lattice.columns; ++k)
      for (std::size_t l = 0; l < lattice.rows; ++l) {
        const Vec a = position(r);
        const Vec b{lattice.x_offset + double(k), lattice.y_offset + double(l), -lattice.depth};
        e += pair(moment(r), substrate_moment, {b[0] - a[0], b[1] - a[1], b[2] - a[2]});
      }
  }
  return e;
}

/// The overdamped model's torques (γ f) and drive force at (θ, t) against central differences of
/// energy(θ, t) in θ_r and in t (F = ∂E/∂ξ, ξ = v (t − t_rest)), to relative `tolerance`.
template <class Model, class Energy>
void check_gradient(const Model& m, const std::vector<double>& theta, double t, Energy&& energy,
                    double tolerance) {
  const double e = 1e-5;
  auto w = rotorsweep::testing::workspace(m);
  std::vector<double> f(theta.size()), q(2);
  m.evaluate(w, theta.data(), t, f.data(), q.data());
  for (std::size_t r = 0; r < theta.size(); ++r) {
    auto plus = theta, minus = theta;
    plus[r] += e;
    minus[r] -= e;
    const double torque = -(energy(plus, t) - energy(minus, t)) / (2 * e);
    CHECK(f[r] * damping == Catch::Detail::Approx(torque).epsilon(tolerance).margin(1e-8));
  }
  const double force = (energy(theta, t + e) - energy(theta, t - e)) / (2 * e * speed);
  CHECK(q[Model::impulse_index] == Catch::Detail::Approx(force).epsilon(tolerance).margin(1e-8));
}

}  // namespace

TEST_CASE("slider: the energy equals the dense dipole sum", "[kernels][slider]") {
  const SliderGrid grid{3, 2};
  const Substrate s(grid, 0.45);
  const auto m = make_model<Overdamped>(grid, parameters<Overdamped>(s));
  const auto theta = random_state(grid.rotors(), 3, 0.0);
  for (const double t : {0.0, 2.0, 17.0}) {
    const double xi = speed * t;
    CHECK(energy_of(m, theta, t) ==
          Catch::Detail::Approx(dense_sum_energy(grid, s.lattice, theta, xi)).epsilon(1e-9));
  }
}

TEST_CASE("slider: torques and the drive's force are minus the energy's gradient", "[kernels][slider]") {
  const SliderGrid grid{4, 3};
  const Substrate s(grid, 0.5);
  const auto m = make_model<Overdamped>(grid, parameters<Overdamped>(s, 1.0));
  const auto theta = random_state(grid.rotors(), 5, 0.0);
  check_gradient(
      m, theta, 7.3, [&](const std::vector<double>& angles, double t) { return energy_of(m, angles, t); },
      1e-7);
}

TEST_CASE("slider: shifted, turned, over turned substrate moments: energy and gradient",
          "[kernels][slider]") {
  const SliderGrid grid{4, 3};
  const SliderPlacement placement{0.4, 0.3, -0.2};  // tilt (rad), shift_x, shift_y (a)
  const Substrate s(grid, 0.45, 35, placement, 0.7);
  const auto m = make_model<Overdamped>(grid, parameters<Overdamped>(s, 1.0), placement);
  const auto theta = random_state(grid.rotors(), 11, 0.0);
  for (const double t : {0.5, 4.0, 13.0}) {
    const double xi = speed * std::max(0.0, t - 1.0);
    CHECK(energy_of(m, theta, t) ==
          Catch::Detail::Approx(dense_sum_energy(grid, s.lattice, theta, xi, placement)).epsilon(1e-8));
  }
  // the default placement and substrate are not this one
  const Substrate plain(grid, 0.45);
  const auto untouched = make_model<Overdamped>(grid, parameters<Overdamped>(plain, 1.0));
  CHECK(std::fabs(energy_of(untouched, theta, 4.0) - energy_of(m, theta, 4.0)) > 1e-3);
  check_gradient(
      m, theta, 7.3,
      [&](const std::vector<double>& angles, double t) {
        return dense_sum_energy(grid, s.lattice, angles, speed * std::max(0.0, t - 1.0), placement);
      },
      1e-6);
}

TEST_CASE("slider: Jacobian, df/dt and integrand gradients match central differences", "[kernels][slider]") {
  const SliderGrid grid{3, 3};
  const Substrate s(grid, 0.4);
  SECTION("with inertia") {
    const auto m = make_model<Inertial>(grid, parameters<Inertial>(s, 0.5));
    rotorsweep::testing::check_linearization(m, random_state(2 * grid.rotors(), 7, 2.0), 3.1);
  }
  SECTION("overdamped") {
    const auto m = make_model<Overdamped>(grid, parameters<Overdamped>(s, 0.5));
    rotorsweep::testing::check_linearization(m, random_state(grid.rotors(), 8, 0.0), 3.1);
  }
}

namespace {

/// The range forms a team uses over `ranks` splits of the rotors (each phase for every rank first)
/// against evaluate and linearize over every rotor: f, K, ∂f/∂t and dq_dy bit for bit, the integrands
/// and their time derivatives (team sums) to rounding.
template <class Model>
void check_range_forms(const Model& m, const std::vector<double>& y, double t) {
  const std::size_t n = m.rotors(), dim = m.dimension();
  auto w = rotorsweep::testing::workspace(m);
  std::vector<double> f(dim), q(2), df_dt(dim), dq_dy(2 * dim), dq_dt(2);
  auto J = rotorsweep::testing::jacobian<typename Model::Jacobian>(dim);
  m.linearize(w, y.data(), t, f.data(), q.data(), J, df_dt.data(), dq_dy.data(), dq_dt.data());
  for (std::size_t ranks : {1u, 2u, 3u, 8u}) {
    INFO(n << " rotors, ranks " << ranks);
    auto w2 = rotorsweep::testing::workspace(m);
    auto J2 = rotorsweep::testing::jacobian<typename Model::Jacobian>(dim);
    std::vector<double> f2(dim), df2(dim), dq2(2 * dim), q2(2), dq_dt2(2);
    typename Model::RotorSums sums;
    std::vector<double> time_sums(2 * ranks), totals(2);
    const auto each_rank = [&](auto&& part) {
      for (std::size_t r = 0; r < ranks; ++r) {
        const TeamRows rows = team_rows(n, ranks, r);
        part(rows.begin, rows.end);
      }
    };
    each_rank([&](std::size_t b, std::size_t e) { m.prepare_range(w2, y.data(), t, true, b, e); });
    each_rank([&](std::size_t b, std::size_t e) { m.torque_range(w2, b, e); });
    each_rank([&](std::size_t b, std::size_t e) {
      const auto part = m.rates_range(w2, y.data(), f2.data(), b, e);
      sums.force += part.force;
      sums.dissipation += part.dissipation;
    });
    for (std::size_t r = 0; r < ranks; ++r) {
      const TeamRows rows = team_rows(n, ranks, r);
      m.jacobian_range(w2, y.data(), t, J2, df2.data(), dq2.data(), time_sums.data() + 2 * r, rows.begin,
                       rows.end);
      totals[0] += time_sums[2 * r];
      totals[1] += time_sums[2 * r + 1];
    }
    m.team_integrands(sums, q2.data());
    m.team_time_derivatives(totals.data(), t, q2.data(), dq_dt2.data());
    CHECK(f2 == f);
    CHECK(df2 == df_dt);
    CHECK(dq2 == dq_dy);
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t k = 0; k < n; ++k) REQUIRE(J2.stiffness().entry(j, k) == J.stiffness().entry(j, k));
    for (std::size_t p = 0; p < 2; ++p) {
      CHECK(q2[p] == Approx(q[p]).epsilon(1e-13).margin(1e-13));
      CHECK(dq_dt2[p] == Approx(dq_dt[p]).epsilon(1e-13).margin(1e-13));
    }
  }
}

}  // namespace

namespace {

/// A member of `m` from y0 over [0, 2π] at rtol 1e-10 by rodas4p2: the lanes' AdaptiveIntegrator
/// against a host team of 1, 2, 3 and 8 ranks (TeamIntegrator over TeamRosenbrock).
template <class Model>
void check_team_follows(const Model& m, const std::vector<double>& y0) {
  const Tolerances tight{1e-10, 1e-10};
  using Lanes = AdaptiveIntegrator<Model, RosenbrockStepper<Model>>;
  auto integrator = rotorsweep::testing::integrator<Lanes>(m, rodas4p2_tableau, tight);
  auto s = rotorsweep::testing::lane_state<double>(m.dimension(), Model::max_quadratures);
  std::copy(y0.begin(), y0.end(), s.y);
  s.t_stop = two_pi;
  integrator.advance(m, s);
  REQUIRE(s.status[0] == LaneStatus::ok);
  using Team = TeamIntegrator<HostTeam, TeamRosenbrock<HostTeam, Model>>;
  const double scale = Lanes::first_step_scale(tight, rodas4p2_tableau);
  for (std::size_t ranks : {1u, 2u, 3u, 8u}) {
    INFO(m.rotors() << " rotors, ranks " << ranks << ", impulse " << s.quad[0]);
    std::vector<double> storage(counted_storage<double>([&](LaneArena<double>& arena) {
      const Team counted(m, ranks, rodas4p2_tableau, tight, StepLimits{}, scale, arena);
    }));
    LaneArena<double> arena(storage.data(), storage.size());
    Team team_integrator(m, ranks, rodas4p2_tableau, tight, StepLimits{}, scale, arena);
    std::vector<double> y = y0;
    TeamMemberState state;
    state.y = y.data();
    state.t_stop = two_pi;
    HostTeam crew(ranks);
    team_integrator.advance(crew, m, state);
    REQUIRE(state.status == LaneStatus::ok);
    double largest = 0.0;
    for (std::size_t k = 0; k < y.size(); ++k) largest = std::max(largest, std::fabs(y[k] - s.y[k]));
    CHECK(largest < 1e-8);
    for (std::size_t p = 0; p < 2; ++p) CHECK(state.quad[p] == Approx(s.quad[p]).epsilon(1e-9).margin(1e-12));
    CHECK(state.steps_accepted + state.steps_rejected ==
          Approx(s.steps_accepted + s.steps_rejected).epsilon(0.01));
  }
}

}  // namespace

TEST_CASE("slider: a member on a team follows the lanes' integration over a period, inertial and overdamped",
          "[kernels][slider][team]") {
  // 5 × 5 rotors, split unevenly by every team of 2 … 8 ranks (7 × 7 took four times as long)
  const SliderGrid grid{5, 5};
  const Substrate s(grid, 0.4);
  check_team_follows(make_model<Inertial>(grid, parameters<Inertial>(s, 0.5)),
                     random_state(2 * grid.rotors(), 21, 0.1));
  check_team_follows(make_model<Overdamped>(grid, parameters<Overdamped>(s, 0.5)),
                     random_state(grid.rotors(), 22, 0.0));
}

TEST_CASE("slider: the range forms over any split of the rotors give the whole slider's bits",
          "[kernels][slider][team]") {
  for (const SliderGrid grid : {SliderGrid{3, 3}, SliderGrid{7, 7}, SliderGrid{1, 2}}) {
    const Substrate s(grid, 0.4);
    check_range_forms(make_model<Inertial>(grid, parameters<Inertial>(s, 0.5)),
                      random_state(2 * grid.rotors(), 11, 2.0), 3.1);
    check_range_forms(make_model<Overdamped>(grid, parameters<Overdamped>(s, 0.5)),
                      random_state(grid.rotors(), 12, 0.0), 3.1);
  }
}

namespace {

/// The state and quadratures of a scalar slider run from y0 over [t0, t1] by Rodas4 at rtol = atol = tol.
template <class Model>
struct Run {
  std::vector<double> y;
  std::array<double, 2> quad{};
};

template <class Model>
Run<Model> integrate(const Model& m, std::vector<double> y0, double t0, double t1, double tol) {
  using Integrator = AdaptiveIntegrator<Model, RosenbrockStepper<Model>>;
  auto integrator = rotorsweep::testing::integrator<Integrator>(m, rodas4_tableau, Tolerances{tol, tol});
  auto s = rotorsweep::testing::lane_state<double>(m.dimension(), Model::max_quadratures);
  for (std::size_t k = 0; k < y0.size(); ++k) s.y[k] = y0[k];
  s.t = t0;
  s.t_stop = t1;
  integrator.advance(m, s);
  REQUIRE(s.status[0] == LaneStatus::ok);
  Run<Model> run;
  run.y.assign(s.y, s.y + m.dimension());
  run.quad = {s.quad[0], s.quad[1]};
  return run;
}

/// Angles of a slider started as the experiment does: rows along x alternately near 0 and π.
std::vector<double> alternating_start(SliderGrid grid, bool with_velocities, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> noise(-two_pi / 96.0, two_pi / 96.0);
  std::vector<double> y(with_velocities ? 2 * grid.rotors() : grid.rotors(), 0.0);
  for (std::size_t r = 0; r < grid.rotors(); ++r)
    y[r] = ((r / grid.columns) % 2 ? 3.141592653589793 : 0.0) + noise(rng);
  return y;
}

/// The 2 × 1 slider by classical RK4 with a fixed step on dense 3-vector sums: τ_r = (∂m_r/∂θ_r)·B at
/// rotor r from the other rotor and the substrate moments, F = ∂E/∂ξ by central differences of
/// dense_sum_energy; returns the angles and ∫F dt over the sliding part.
std::pair<std::vector<double>, double> dense_reference(const SubstrateLattice& lattice, std::vector<double> y,
                                                       double rest, double t1, double h) {
  const SliderGrid grid{2, 1};
  using Vec = std::array<double, 3>;
  const auto field_at = [](const Vec& m, const Vec& r) {  // r from the source to the point
    const double d = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
    const double mr = (m[0] * r[0] + m[1] * r[1] + m[2] * r[2]) / d;
    Vec b;
    for (int c = 0; c < 3; ++c) b[c] = (3.0 * mr * r[c] / d - m[c]) / (d * d * d);
    return b;
  };
  const auto rates = [&](const std::vector<double>& s, double t, std::vector<double>& f) {
    const double xi = speed * std::max(0.0, t - rest);
    for (std::size_t r = 0; r < 2; ++r) {
      const std::size_t other = 1 - r;
      Vec b = field_at({std::cos(s[other]), 0.0, -std::sin(s[other])}, {double(r) - double(other), 0.0, 0.0});
      for (std::size_t k = 0; k < lattice.columns; ++k)
        for (std::size_t l = 0; l < lattice.rows; ++l) {
          const Vec bs = field_at({moment_ratio, 0.0, 0.0}, {double(r) + xi - (lattice.x_offset + double(k)),
                                                             -(lattice.y_offset + double(l)), lattice.depth});
          for (int c = 0; c < 3; ++c) b[c] += bs[c];
        }
      const double torque = -std::sin(s[r]) * b[0] - std::cos(s[r]) * b[2];
      f[r] = s[2 + r];
      f[2 + r] = (torque - damping * s[2 + r]) / inertia;
    }
    const double e = 1e-6;
    f[4] = t > rest
               ? (dense_sum_energy(grid, lattice, s, xi + e) - dense_sum_energy(grid, lattice, s, xi - e)) /
                     (2 * e)
               : 0.0;
  };
  y.push_back(0.0);  // ∫F dt
  std::vector<double> k1(5), k2(5), k3(5), k4(5), tmp(5);
  // two legs, so that the start of sliding (a kink in ξ) falls on a step boundary
  for (const auto& [begin, end] : {std::pair{0.0, rest}, {rest, t1}}) {
    const auto steps = std::size_t(std::ceil((end - begin) / h));
    const double dt = (end - begin) / double(steps);
    for (std::size_t i = 0; i < steps; ++i) {
      const double t = begin + double(i) * dt;
      rates(y, t, k1);
      for (int c = 0; c < 5; ++c) tmp[c] = y[c] + 0.5 * dt * k1[c];
      rates(tmp, t + 0.5 * dt, k2);
      for (int c = 0; c < 5; ++c) tmp[c] = y[c] + 0.5 * dt * k2[c];
      rates(tmp, t + 0.5 * dt, k3);
      for (int c = 0; c < 5; ++c) tmp[c] = y[c] + dt * k3[c];
      rates(tmp, t + dt, k4);
      for (int c = 0; c < 5; ++c) y[c] += dt / 6.0 * (k1[c] + 2 * k2[c] + 2 * k3[c] + k4[c]);
    }
  }
  return {{y[0], y[1], y[2], y[3]}, y[4]};
}

}  // namespace

TEST_CASE("slider: a 2 x 1 slider equals a dense-sum RK4 reference", "[kernels][slider]") {
  const SliderGrid grid{2, 1};
  const Substrate s(grid, 0.5, 15);
  const double rest = 1.0, t1 = 1.0 + two_pi;  // one substrate period of sliding
  const auto m = make_model<Inertial>(grid, parameters<Inertial>(s, rest));
  const std::vector<double> y0{0.3, 2.9, 0.0, 0.0};
  const auto [reference, reference_impulse] = dense_reference(s.lattice, y0, rest, t1, 5e-4);
  const auto before = integrate(m, y0, 0.0, rest, 1e-10);
  const auto run = integrate(m, before.y, rest, t1, 1e-10);
  const double impulse = run.quad[Inertial::impulse_index];  // each run starts its quadratures at 0
  for (std::size_t r = 0; r < 2; ++r) CHECK(std::fabs(run.y[r] - reference[r]) < 1e-9);
  INFO("impulse " << impulse << " reference " << reference_impulse);
  CHECK(std::fabs(impulse - reference_impulse) < 1e-9 * (1.0 + std::fabs(reference_impulse)));
}

TEST_CASE("slider: without damping and drive the energy is conserved", "[kernels][slider]") {
  const SliderGrid grid{3, 3};
  const Substrate s(grid, 0.5);
  auto p = parameters<Inertial>(s);
  p.damping = 0.0;
  p.speed = 0.0;
  const auto m = make_model<Inertial>(grid, p);
  const auto y0 = alternating_start(grid, true, 11);
  const auto total = [&](const std::vector<double>& y) {
    return energy_of(m, y, 0.0) + m.kinetic_energy(y.data());
  };
  // about 20 oscillations of the stiffest mode
  for (const double tol : {1e-7, 1e-9}) {
    const auto run = integrate(m, y0, 0.0, 0.3, tol);
    const double drift = std::fabs(total(run.y) - total(y0));
    INFO("tol " << tol << " energy drift " << drift << " of " << total(y0));
    CHECK(drift < 100.0 * tol * std::fabs(total(y0)));
    CHECK(run.quad[Inertial::dissipation_index] == 0.0);
  }
}

TEST_CASE("slider: the drive's work equals dissipation plus stored energy over a period",
          "[kernels][slider]") {
  const SliderGrid grid{3, 3};
  const Substrate s(grid, 0.45);
  const double rest = 0.5;
  SECTION("with inertia") {
    const auto m = make_model<Inertial>(grid, parameters<Inertial>(s, rest));
    const auto start = integrate(m, alternating_start(grid, true, 12), 0.0, rest, 1e-9);
    const auto run = integrate(m, start.y, rest, rest + two_pi, 1e-9);
    const double work = speed * run.quad[0];  // each run starts its quadratures at 0
    const double stored = energy_of(m, run.y, rest + two_pi) + m.kinetic_energy(run.y.data()) -
                          energy_of(m, start.y, rest) - m.kinetic_energy(start.y.data());
    const double dissipated = run.quad[1];
    INFO("work " << work << " dissipated " << dissipated << " stored " << stored);
    CHECK(dissipated > 0.0);
    CHECK(std::fabs(work - dissipated - stored) < 1e-6 * (std::fabs(work) + std::fabs(dissipated)));
  }
  SECTION("overdamped") {
    const auto m = make_model<Overdamped>(grid, parameters<Overdamped>(s, rest));
    const auto start = integrate(m, alternating_start(grid, false, 12), 0.0, rest, 1e-9);
    const auto run = integrate(m, start.y, rest, rest + two_pi, 1e-9);
    const double work = speed * run.quad[0];  // each run starts its quadratures at 0
    const double stored = energy_of(m, run.y, rest + two_pi) - energy_of(m, start.y, rest);
    const double dissipated = run.quad[1];
    INFO("work " << work << " dissipated " << dissipated << " stored " << stored);
    CHECK(std::fabs(work - dissipated - stored) < 1e-6 * (std::fabs(work) + std::fabs(dissipated)));
  }
}

TEST_CASE("slider: as the inertia vanishes the motion approaches the overdamped one", "[kernels][slider]") {
  const SliderGrid grid{3, 2};
  const Substrate s(grid, 0.45);
  const auto over = make_model<Overdamped>(grid, parameters<Overdamped>(s));
  const auto y0 = alternating_start(grid, false, 13);
  const auto limit = integrate(over, y0, 0.0, two_pi, 1e-10);
  std::vector<double> distance;
  for (const double factor : {1e-1, 1e-2, 1e-3}) {
    auto p = parameters<Inertial>(s);
    p.inertia = factor * inertia;
    const auto m = make_model<Inertial>(grid, p);
    auto start = y0;
    start.resize(2 * grid.rotors(), 0.0);
    const auto run = integrate(m, start, 0.0, two_pi, 1e-10);
    double d = 0.0;
    for (std::size_t r = 0; r < grid.rotors(); ++r) d = std::max(d, std::fabs(run.y[r] - limit.y[r]));
    distance.push_back(d);
  }
  INFO("max angle difference at I x 0.1, 0.01, 0.001: " << distance[0] << " " << distance[1] << " "
                                                        << distance[2]);
  CHECK(distance[1] < 0.2 * distance[0]);
  CHECK(distance[2] < 0.2 * distance[1]);
  CHECK(distance[2] < 1e-3);
}

TEST_CASE("slider: SIMD lanes equal scalar ones bit for bit", "[kernels][slider]") {
  const SliderGrid grid{3, 2};
  constexpr std::size_t W = lane_width<simd_lane>;
  std::vector<Substrate> substrates;
  for (std::size_t l = 0; l < W; ++l) substrates.emplace_back(grid, 0.35 + 0.05 * double(l));
  using Simd = SliderModel<simd_lane, true>;
  auto arena = scratch<simd_lane>(Simd::storage_size(grid));
  Simd vm(grid, SliderPlacement{}, arena);
  for (std::size_t l = 0; l < W; ++l) vm.set_lane(l, parameters<Simd>(substrates[l], 0.3));
  using Integrator = AdaptiveIntegrator<Simd, RosenbrockStepper<Simd>>;
  auto vi = rotorsweep::testing::integrator<Integrator>(vm, rodas4_tableau, Tolerances{1e-7, 1e-7});
  auto vs = rotorsweep::testing::lane_state<simd_lane>(vm.dimension(), 2);
  const auto y0 = alternating_start(grid, true, 14);
  for (std::size_t k = 0; k < y0.size(); ++k) vs.y[k] = simd_lane(y0[k]);
  vs.t_stop = simd_lane(2.0);
  vi.advance(vm, vs);
  for (std::size_t l = 0; l < W; ++l) {
    const auto m = make_model<Inertial>(grid, parameters<Inertial>(substrates[l], 0.3));
    const auto run = integrate(m, y0, 0.0, 2.0, 1e-7);
    for (std::size_t k = 0; k < y0.size(); ++k) CHECK(lane_get(vs.y[k], l) == run.y[k]);
    CHECK(lane_get(vs.quad[0], l) == run.quad[0]);
  }
}
