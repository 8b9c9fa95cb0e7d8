// The GPU sweep of a variant whose members run in registers (docs/architecture.md "Register kernels"):
// a persistent grid whose groups of L threads each take the next member from a counter and run it
// with RegisterMember on a DeviceWarp<L>; the host's chunks as for the other kernels (run_chunks).
#pragma once

#include <cuda_runtime.h>

#include <stdexcept>

#include "ensemble/gpu/gpu_registers.hpp"
#include "ensemble/gpu/gpu_runner.cuh"
#include "ensemble/gpu/register_member.hpp"
#include "kernels/lanes/warp.hpp"

namespace rotorsweep::ensemble::gpu {

/// Members of a chunk, one per L threads: the group's first thread claims the next member for all.
template <std::size_t L, std::size_t R, bool PerRow, std::size_t S, bool Q>
__device__ __forceinline__ void take_members_in_registers(const SlotSchedule& schedule,
                                                          const SlotViews& slots, unsigned long long count,
                                                          unsigned long long* next) {
  using W = kernels::DeviceWarp<L>;
  for (;;) {
    unsigned long long k = 0;
    if (W::rank() == 0) k = atomicAdd(next, 1ull);
    k = __shfl_sync(W::group(), k, 0, int(L));
    if (k >= count) return;
    RegisterMember<W, R, PerRow, S, Q>::run(schedule, slots, std::size_t(k));
  }
}

/// The register kernel of a shape without an occupancy bound: ptxas takes the registers it wants.
template <std::size_t L, std::size_t R, bool PerRow, std::size_t S, bool Q>
__global__ void sweep_in_registers(const __grid_constant__ SlotSchedule schedule, SlotViews slots,
                                   unsigned long long count, unsigned long long* next) {
  take_members_in_registers<L, R, PerRow, S, Q>(schedule, slots, count, next);
}

/// The same for a shape bounded to B blocks of 128 threads per multiprocessor (RegisterShape::blocks):
/// at most 65 536 / (128 B) registers per thread, the rest spilled to local memory.
template <std::size_t L, std::size_t R, bool PerRow, std::size_t S, unsigned B, bool Q>
__global__ void __launch_bounds__(128 * B)
    sweep_in_registers_bounded(const __grid_constant__ SlotSchedule schedule, SlotViews slots,
                               unsigned long long count, unsigned long long* next) {
  take_members_in_registers<L, R, PerRow, S, Q>(schedule, slots, count, next);
}

/// The variant's members in registers on L lanes × R slots with S stage vectors, bounded to B blocks,
/// carrying every quadrature where Q (the shape of compiled_register_shapes that the variant's plan holds).
template <std::size_t L, std::size_t R, bool PerRow, std::size_t S, unsigned B, bool Q>
SweepOutcome run_in_registers(const Scene& scene, const VariantRange& range, const GpuPlan& plan,
                              const RunControl& control, const ResultSink& sink) {
  using Integrator =
      DeviceAdaptiveIntegrator<kernels::StepperFamily::rosenbrock, kernels::NearestNeighbourRows<double>>;
  available_gpu();
  const Member variant = range.source->at(range.begin);
  const SlotSchedule schedule =
      slot_schedule(scene, variant, device_first_step_scale<Integrator>(scene, variant));
  using Driver = RegisterMember<kernels::DeviceWarp<L>, R, PerRow, S, Q>;
  static_assert(RegisterMemberForm<Driver, SlotSchedule, SlotViews, kernels::Integrals>);
  constexpr RegisterShape shape{L, R, PerRow, S, B, Q};
  if (!Driver::fits(schedule, shape.carriable()) || std::size_t(schedule.methods.rosenbrock.stages) > S)
    throw std::logic_error("a register kernel cannot run this schedule");
  const auto kernel = [] {
    if constexpr (B > 0)
      return sweep_in_registers_bounded<L, R, PerRow, S, B, Q>;
    else
      return sweep_in_registers<L, R, PerRow, S, Q>;
  }();
  if (plan.threads_per_block > shape.max_threads_per_block())
    throw std::logic_error("a register kernel cannot run blocks of this size");
  ChunkGrid grid{resident_blocks(kernel, plan, 0), plan.threads_per_block, 0, 0};
  grid.resident = std::size_t(grid.blocks) * std::size_t(grid.threads_per_block) / L;
  return run_chunks(scene, range, schedule, grid, plan, control, sink,
                    [&](cudaStream_t stream, const SlotSchedule& chunk_schedule, const SlotViews& views,
                        unsigned long long count, unsigned long long* counter) {
                      kernel<<<grid.blocks, grid.threads_per_block, 0, stream>>>(chunk_schedule, views, count,
                                                                                 counter);
                    });
}

}  // namespace rotorsweep::ensemble::gpu
