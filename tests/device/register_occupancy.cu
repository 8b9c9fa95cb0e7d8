// The register kernel of N = 8 … 24 (8 lanes × 3 rows, six stage vectors) compiled for sm_90 unbounded
// and bounded to 3 blocks of 128 threads per SM: tests/scripts/register_occupancy.sh reads ptxas's
// registers and stack frames for both and states the warps each keeps resident (docs/performance.md).
#include "ensemble/gpu/gpu_register_sweep.cuh"

namespace rotorsweep::ensemble::gpu {

template __global__ void sweep_in_registers<8, 3, false, 6, false>(const __grid_constant__ SlotSchedule,
                                                                   SlotViews, unsigned long long,
                                                                   unsigned long long*);
template __global__ void sweep_in_registers_bounded<8, 3, false, 6, 3, false>(
    const __grid_constant__ SlotSchedule, SlotViews, unsigned long long, unsigned long long*);

}  // namespace rotorsweep::ensemble::gpu
