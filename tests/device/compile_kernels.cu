// The kernels compiled for a GPU (nvcc, no GPU needed): the row model and both stepper families on the
// double lane, and on warp teams the stage solves (ring, dense, slider) and whole members
// (nearest neighbours at T = 0 and T > 0, a coupling table at T = 0, the slider's), and members in a
// warp's registers; each member form's driver checked against its concept (ensemble/engine/member_forms.hpp).
#include "ensemble/engine/member_forms.hpp"
#include "ensemble/rows/device_member.hpp"
#include "ensemble/rows/team_member.hpp"
#include "ensemble/rows/warp_member.hpp"
#include "ensemble/slider/slider_team_member.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/lanes/lane_math.hpp"
#include "kernels/lanes/team.hpp"
#include "kernels/lanes/warp.hpp"
#include "kernels/linear/team_cyclic_tridiagonal.hpp"
#include "kernels/linear/team_dense_symmetric.hpp"
#include "kernels/linear/team_second_order_jacobian.hpp"
#include "kernels/models/rows/coupled_rows.hpp"
#include "kernels/models/rows/nearest_neighbour_rows.hpp"
#include "kernels/models/rows/row_models_on_teams.hpp"
#include "kernels/models/rows/warp_rows.hpp"
#include "kernels/models/slider/slider_model.hpp"
#include "kernels/models/slider/slider_on_teams.hpp"
#include "kernels/steppers/adaptive_integrator.hpp"
#include "kernels/steppers/stepper_list.hpp"
#include "kernels/steppers/team_integrator.hpp"
#include "kernels/steppers/team_leimkuhler_matthews.hpp"
#include "kernels/steppers/team_rosenbrock.hpp"
#include "kernels/steppers/warp_member_form.hpp"
#include "kernels/steppers/warp_rosenbrock.hpp"

using namespace rotorsweep::kernels;

using Model = NearestNeighbourRows<double>;

template <class Stepper>
__global__ void advance_members(StepperMethods methods, double* storage, std::size_t per_thread,
                                std::size_t rows, const double* A, const double* g, double* dissipation) {
  const std::size_t member = blockIdx.x * blockDim.x + threadIdx.x;
  LaneArena<double> arena(storage + member * per_thread, per_thread);
  const Model model(rows, arena, all_integrals, {A[member], g[member], false});
  AdaptiveIntegrator<Model, Stepper> integrator(model, methods.get<typename Stepper::Method>(), {1e-6, 1e-9},
                                                {}, arena);
  LaneState<double> state(rows, Model::max_quadratures, arena);
  for (std::size_t j = 0; j < rows; ++j) state.y[j] = 3.14159 * double(j % 2) + 0.01 * double(j);
  state.t_stop = two_pi;
  integrator.advance(model, state);
  double s = 0, c = 0;
  lane_sincos(state.y[0], s, c);
  dissipation[member] = state.quad[0] + 0.0 * s * c;
}

template __global__ void advance_members<RosenbrockStepper<Model>>(StepperMethods, double*, std::size_t,
                                                                   std::size_t, const double*, const double*,
                                                                   double*);
template __global__ void advance_members<DormandPrince5<Model>>(StepperMethods, double*, std::size_t,
                                                                std::size_t, const double*, const double*,
                                                                double*);

/// The stage solves on a warp team: each team of `team_size` threads factors and solves one member's
/// ring (kernels/linear/team_cyclic_tridiagonal.hpp), its dense coupled rows (team_dense_symmetric.hpp)
/// and an inertial slider's (team_second_order_jacobian.hpp) over its part of `storage`, in place on
/// its 2 N values of `rhs`.
__global__ void solve_on_teams(double* storage, std::size_t per_team, std::size_t rows, unsigned team_size,
                               double* rhs, int* definite) {
  const std::size_t team = (blockIdx.x * std::size_t(blockDim.x) + threadIdx.x) / team_size;
  const WarpTeam crew(team_size);
  LaneArena<double> arena(storage + team * per_team, per_team);
  TeamCyclicTridiagonal<const WarpTeam> J(rows, team_size, arena);
  TeamDenseSymmetric<const WarpTeam> coupled(rows, team_size, arena);
  TeamSecondOrderJacobian<const WarpTeam, true> slider(2 * rows, team_size, arena);
  slider.set_dynamics(0.7, 0.2);
  crew.sync();
  crew.each([&](std::size_t rank) {
    const TeamRows mine = team_rows(rows, team_size, rank);
    for (std::size_t i = mine.begin; i < mine.end; ++i) {
      J.diag(i) = -2.0 + 0.01 * double(i % 7);
      J.off(i) = 0.3;
      for (std::size_t k = 0; k < rows; ++k)
        coupled.entry(i, k) = slider.stiffness().entry(i, k) = i == k ? -2.0 : 0.1 / double(1 + (i + k) % 5);
    }
  });
  J.factor(crew, 3.0);
  J.solve(crew, rhs + 2 * team * rows);
  coupled.factor(crew, 3.0);
  coupled.solve(crew, rhs + 2 * team * rows);
  slider.factor(crew, 3.0);
  slider.solve(crew, rhs + 2 * team * rows);
  if (crew.rank() == 0)
    definite[team] =
        J.positive_definite() && coupled.positive_definite() && slider.positive_definite() ? 1 : 0;
}

/// A member of the nearest-neighbour rows integrated by a warp team over one period (team_integrator.hpp).
__global__ void advance_on_teams(const __grid_constant__ RosenbrockTableau method, double* storage, std::size_t per_team,
                                 std::size_t rows, unsigned team_size, const double* A, double* theta,
                                 double* drive) {
  using Stepper = TeamRosenbrock<const WarpTeam, Model>;
  const std::size_t team = (blockIdx.x * std::size_t(blockDim.x) + threadIdx.x) / team_size;
  const WarpTeam crew(team_size);
  LaneArena<double> arena(storage + team * per_team, per_team);
  const Model model(rows, arena, Integrals{true, false, false, true, false, false}, {A[team], 0.0011, false});
  TeamIntegrator<const WarpTeam, Stepper> integrator(model, team_size, method, {1e-6, 1e-9}, {}, 1e-3, arena);
  crew.sync();
  TeamMemberState state;
  state.y = theta + team * rows;
  state.t_stop = two_pi;
  integrator.advance(crew, model, state);
  if (crew.rank() == 0) drive[team] = state.quad[0];
}

/// Slider members of a chunk of slots (7 × 7 inertial on the GPU's runs), one per warp team, from start
/// to retirement (ensemble/slider/slider_team_member.hpp: SliderModel's range forms,
/// TeamSecondOrderJacobian).
__global__ void run_slider_members_on_teams(rotorsweep::ensemble::SliderSlotSchedule schedule,
                                            rotorsweep::ensemble::SliderSlotViews slots, double* storage,
                                            std::size_t per_team, unsigned team_size) {
  using Stepper = TeamRosenbrock<const WarpTeam, SliderModel<double, true>>;
  const std::size_t team = (blockIdx.x * std::size_t(blockDim.x) + threadIdx.x) / team_size;
  const WarpTeam crew(team_size);
  rotorsweep::ensemble::SliderTeamMember<const WarpTeam, TeamIntegrator<const WarpTeam, Stepper>>::run(
      crew, schedule, slots, team, storage + team * per_team, per_team);
}

/// Members of a chunk of slots of the row model Rows, one per warp team, from start to retirement
/// (ensemble/rows/team_member.hpp; for a coupling table CoupledRows' range forms and TeamDenseSymmetric).
template <class Rows>
__global__ void run_members_on_teams(rotorsweep::ensemble::SlotSchedule schedule,
                                     rotorsweep::ensemble::SlotViews slots, double* storage,
                                     std::size_t per_team, unsigned team_size) {
  using Stepper = TeamRosenbrock<const WarpTeam, Rows>;
  const std::size_t team = (blockIdx.x * std::size_t(blockDim.x) + threadIdx.x) / team_size;
  const WarpTeam crew(team_size);
  rotorsweep::ensemble::TeamMember<const WarpTeam, TeamIntegrator<const WarpTeam, Stepper>>::run(
      crew, schedule, slots, team, storage + team * per_team, per_team);
}

template __global__ void run_members_on_teams<Model>(rotorsweep::ensemble::SlotSchedule,
                                                     rotorsweep::ensemble::SlotViews, double*, std::size_t,
                                                     unsigned);
template __global__ void run_members_on_teams<CoupledRows<double>>(rotorsweep::ensemble::SlotSchedule,
                                                                   rotorsweep::ensemble::SlotViews, double*,
                                                                   std::size_t, unsigned);

/// Members at T > 0, one per warp team (kernels/steppers/team_leimkuhler_matthews.hpp).
__global__ void run_thermal_members_on_teams(rotorsweep::ensemble::SlotSchedule schedule,
                                             rotorsweep::ensemble::SlotViews slots, double* storage,
                                             std::size_t per_team, unsigned team_size) {
  const std::size_t team = (blockIdx.x * std::size_t(blockDim.x) + threadIdx.x) / team_size;
  const WarpTeam crew(team_size);
  rotorsweep::ensemble::TeamMember<const WarpTeam, TeamLeimkuhlerMatthews<const WarpTeam, Model>>::run(
      crew, schedule, slots, team, storage + team * per_team, per_team);
}

/// Members of disordered nearest-neighbour rows in registers, each on L threads of a warp with R rows
/// apiece and every quadrature (ensemble/rows/warp_member.hpp): 8 × 3 (N ≤ 24); the GPU backend's
/// own register kernels carry R and ρ̄ (docs/performance.md "Rows in registers: what ptxas says").
template <std::size_t L, std::size_t R>
__global__ void run_members_in_registers(const __grid_constant__ rotorsweep::ensemble::SlotSchedule schedule,
                                         rotorsweep::ensemble::SlotViews slots) {
  using Rows = WarpRows<DeviceWarp<L>, R, true, all_integrals>;
  using Driver = rotorsweep::ensemble::WarpMember<Rows, WarpIntegrator<Rows, WarpRosenbrock<Rows, 8>>>;
  static_assert(rotorsweep::ensemble::RegisterMemberForm<Driver, rotorsweep::ensemble::SlotSchedule,
                                                         rotorsweep::ensemble::SlotViews, Integrals>);
  Driver::run(schedule, slots, (blockIdx.x * std::size_t(blockDim.x) + threadIdx.x) / L);
}

template __global__ void run_members_in_registers<8, 3>(
    const __grid_constant__ rotorsweep::ensemble::SlotSchedule, rotorsweep::ensemble::SlotViews);

namespace forms {
using rotorsweep::ensemble::SlotSchedule;
using rotorsweep::ensemble::SlotViews;
using Rosenbrock = RosenbrockStepper<Model>;
static_assert(rotorsweep::ensemble::ThreadMemberForm<
              rotorsweep::ensemble::DeviceMember<Model, AdaptiveIntegrator<Model, Rosenbrock>>, SlotSchedule, SlotViews>);
static_assert(rotorsweep::ensemble::TeamMemberForm<
              rotorsweep::ensemble::TeamMember<const WarpTeam, TeamIntegrator<const WarpTeam, TeamRosenbrock<const WarpTeam, Model>>>,
              const WarpTeam, SlotSchedule, SlotViews>);
}  // namespace forms
