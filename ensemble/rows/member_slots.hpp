// Members laid out as flat arrays for a device backend (docs/architecture.md "Backends"): a chunk
// of members' inputs (parameters, disorder, couplings, noise keys, y(0)) and the slots their retired
// lanes write (status, counts, the last period records, end states and row profiles), with the
// host side that fills and reads them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "ensemble/engine/member_progress.hpp"
#include "ensemble/engine/slot_buffer.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/member_result.hpp"
#include "ensemble/rows/scene.hpp"
#include "ensemble/rows/sweep.hpp"
#include "kernels/lanes/host_device.hpp"
#include "kernels/lanes/lane_arena.hpp"
#include "kernels/steppers/stepper_list.hpp"

namespace rotorsweep::ensemble {

/// What every member of a variant shares: its schedule, tolerances and the record ring's size.
struct SlotSchedule {
  std::size_t rows = 0;
  StopSchedule periods{};
  double steady_tol = 0;  ///< the steady test's tolerance (SteadyDissipation), with periods.steady_test
  bool wrap_angles = false;
  bool slips = false;          ///< the slip counter is on
  bool slip_energies = false;  ///< it records each slip's energy (observables.slip_kinds)
  double slip_rate = 0;
  kernels::StepperMethods methods{};  ///< the scene's stepper's tableau (kernels::stepper_methods)
  double rtol = 0, atol = 0, h_max = 0, max_steps = 0;
  double error_rtol = 0;  ///< rtol × the stepper's swing_error_factor (channel dissipation_error)
  kernels::StepController controller = kernels::StepController::integral;
  double first_step_scale = 0;       ///< computed on the host (kernels::AdaptiveIntegrator)
  std::size_t record_capacity = 0;   ///< period records a slot keeps (a ring)
  std::size_t end_capacity = 4;      ///< period end states a slot keeps (a ring, end_state_capacity)
  kernels::Integrals quadratures{};  ///< what the row model carries (the scene's observables)
  QuadratureChannels channels{};     ///< the period channels those quadratures fill
  /// The Langevin stepper's settings (stochastic: thermal.temperature > 0).
  bool stochastic = false;
  double temperature = 0, step_fraction = 0;
  int steps_per_period = 0;
  /// Row profiles: on, the links a member has (N, or N − 1 on open rows), and the averaged periods'
  /// profiles a slot keeps (a ring of average_periods, each 2N values: rows, then links).
  bool row_profiles = false;
  std::size_t links = 0, profile_capacity = 0;
  /// Which disorder arrays the members carry (each N values per member).
  bool A_rows = false, anisotropy_rows = false, coupling_rows = false;
  /// The coupling table of CoupledRows (its b, c are inputs of the chunk): a, range, open rows.
  double coupling_a = 0;
  std::size_t coupling_range = 0;
  bool open = false;
};

/// Device-visible views of a chunk of `count` members: inputs, then outputs (k: the chunk position).
struct SlotViews {
  const double* A = nullptr;                 ///< [k]
  const double* g = nullptr;                 ///< [k]
  const std::uint8_t* strict_fm = nullptr;   ///< [k]
  const double* y0 = nullptr;                ///< [k · rows + j]
  const double* tolerance_scale = nullptr;   ///< [k] Member::tolerance_scale
  const double* A_rows = nullptr;            ///< [k · rows + j] δ_j, where SlotSchedule::A_rows
  const double* anisotropy_rows = nullptr;   ///< [k · rows + j] α_j, where SlotSchedule::anisotropy_rows
  const double* coupling_rows = nullptr;     ///< [k · rows + j] β_j, where SlotSchedule::coupling_rows
  const std::uint64_t* noise_key = nullptr;  ///< [k] the thermal noise stream's key
  const double* table_b = nullptr;           ///< [u − 1] b_u of the coupling table
  const double* table_c = nullptr;           ///< [u − 1] c_u
  std::uint8_t* status = nullptr;            ///< [k] kernels::LaneStatus
  std::uint8_t* settled = nullptr;           ///< [k]
  std::int32_t* periods = nullptr;           ///< [k] periods closed
  double* steps = nullptr;                   ///< [2k] accepted, [2k + 1] rejected
  double* theta = nullptr;                   ///< [k · rows + j] the state at retirement
  double* records = nullptr;  ///< [(k · record_capacity + r) · channel_count + c], r = period mod capacity
  double* end_states = nullptr;  ///< [(k · end_capacity + r) · rows + j], r = period mod end_capacity
  double* profiles = nullptr;  ///< [(k · profile_capacity + r) · 2 rows + j], r = period mod profile_capacity
};

/// The model of a chunk's members on one lane's arena: a row model carries the quadratures of the
/// scene's observables; another model (SingleRotor) is made from its size alone.
template <class Model>
ROTORSWEEP_HD Model slot_model(const SlotSchedule& s, kernels::LaneArena<double>& arena) {
  if constexpr (requires { Model(s.rows, arena, s.quadratures); })
    return Model(s.rows, arena, s.quadratures);
  else
    return Model(s.rows, arena);
}

/// The parameters of chunk member k for Model (NearestNeighbourRows with its disorder, or
/// CoupledRows with the chunk's table), as RowSetup gives them on the CPU; a model without the
/// strict-FM mark or disorder takes A and g alone.
template <class Model>
ROTORSWEEP_HD typename Model::Parameters slot_parameters(const SlotSchedule& s, const SlotViews& v,
                                                         std::size_t k) {
  typename Model::Parameters p{};
  p.A = v.A[k];
  p.g = v.g[k];
  if constexpr (requires { p.strict_fm; }) p.strict_fm = v.strict_fm[k] != 0;
  if constexpr (requires { p.range; }) {
    p.a = s.coupling_a;
    p.b = v.table_b;
    p.c = v.table_c;
    p.range = s.coupling_range;
    p.open = s.open;
  }
  if constexpr (requires { p.A_rows; }) {
    const std::size_t at = k * s.rows;
    p.A_rows = s.A_rows ? v.A_rows + at : nullptr;
    p.anisotropy_rows = s.anisotropy_rows ? v.anisotropy_rows + at : nullptr;
  }
  if constexpr (requires { p.coupling_rows; })
    p.coupling_rows = s.coupling_rows ? v.coupling_rows + k * s.rows : nullptr;
  return p;
}

/// Views over the buffers of a chunk given in SlotChunk::buffers() order (host or device memory).
inline SlotViews slot_views(void* const* p) {
  return {static_cast<const double*>(p[0]),
          static_cast<const double*>(p[1]),
          static_cast<const std::uint8_t*>(p[2]),
          static_cast<const double*>(p[3]),
          static_cast<const double*>(p[4]),
          static_cast<const double*>(p[5]),
          static_cast<const double*>(p[6]),
          static_cast<const double*>(p[7]),
          static_cast<const std::uint64_t*>(p[8]),
          static_cast<const double*>(p[9]),
          static_cast<const double*>(p[10]),
          static_cast<std::uint8_t*>(p[11]),
          static_cast<std::uint8_t*>(p[12]),
          static_cast<std::int32_t*>(p[13]),
          static_cast<double*>(p[14]),
          static_cast<double*>(p[15]),
          static_cast<double*>(p[16]),
          static_cast<double*>(p[17]),
          static_cast<double*>(p[18])};
}

/// Host buffers of one chunk in the SlotViews layout.
class SlotChunk {
 public:
  SlotChunk(const SlotSchedule& schedule, std::size_t capacity);

  /// Fills the inputs of `members` (at most capacity, all of one variant).
  void fill(const Scene& scene, std::span<const Member> members);
  /// The schedule the next members run (another of the variant's: a shadow run's, shadow_slot_schedule),
  /// whose disorder arrays the chunk holds (made with the schedule whose arrays cover both).
  void set_schedule(const SlotSchedule& schedule);
  /// The result of chunk member k, read from the outputs.
  MemberResult result(const Scene& scene, std::size_t k) const;
  /// Hands every member and its result to sink(member, result) (on `threads` host threads); returns
  /// their step attempts.
  using Sink = std::function<void(const Member&, MemberResult&&)>;
  double deliver(const Scene& scene, int threads, const Sink& sink) const;

  /// Views of these host buffers (for the host run of the device driver, and for copies).
  SlotViews views();
  std::size_t count() const { return count_; }
  std::size_t capacity() const { return capacity_; }
  const SlotSchedule& schedule() const { return schedule_; }

  /// Each buffer in SlotViews order, inputs first (for copies to and from a device).
  using Buffer = SlotBuffer;
  std::vector<Buffer> buffers();

 private:
  SlotSchedule schedule_;
  std::size_t capacity_, count_ = 0;
  std::vector<Member> members_;  ///< each chunk member (its plan index, a rerun's kind)
  std::vector<double> A_, g_, y0_, tolerance_scale_, A_rows_, anisotropy_rows_, coupling_rows_;
  std::vector<std::uint64_t> noise_key_;
  std::vector<double> table_b_, table_c_;  ///< the coupling table, filled once
  bool table_filled_ = false;
  std::vector<std::uint8_t> strict_fm_, status_, settled_;
  std::vector<std::int32_t> periods_;
  std::vector<double> steps_, theta_, records_, end_states_, profiles_;
};

/// The schedule of a variant's members: the scene's schedule with the variant's tolerances,
/// `first_step_scale` the stepper's first-step scale at them (0 for the Langevin stepper).
SlotSchedule slot_schedule(const Scene& scene, const Member& variant, double first_step_scale);
/// The schedule of the reruns of `primary`'s members, shadow runs and symmetry probes
/// (Scene::shadow_schedule): the same slots, and A's deviations where probes run (runs_probes).
SlotSchedule shadow_slot_schedule(const Scene& scene, const SlotSchedule& primary);

}  // namespace rotorsweep::ensemble
