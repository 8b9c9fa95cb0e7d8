// A variant's row members through chunks of member slots on a device (docs/architecture.md "Backends"):
// two chunks in flight, and the reruns their members need run as chunks of their own between the plan's.
#pragma once

#include <cstddef>

#include "ensemble/engine/slot_device.hpp"
#include "ensemble/rows/member_slots.hpp"
#include "ensemble/rows/scene.hpp"
#include "ensemble/rows/sweep.hpp"

namespace rotorsweep::ensemble {

/// What runs chunks of row slots: the GPU's kernels (ensemble/gpu/gpu_runner.cuh), the host in tests.
/// start(chunk, slot) runs with chunk.schedule(), a plan's or its shadow runs'.
using RowSlotDevice = SlotDevice<SlotChunk>;

/// The members of `range` with `schedule` in chunks of up to `capacity` on `device`, two in flight
/// (run_group_in_chunks): while the device runs one chunk the host fills the next and delivers
/// the one before (summaries on the control's threads). Members are taken in plan order, or one by one
/// through the control's claim where it has one (the ranks of mpirun, each with its device). A member that
/// needs a shadow run is held (RowReruns) and its shadow queued; the queued shadows run as a chunk of their
/// own (shadow_slot_schedule) once they fill one or the plan has run out, and each completes its primary,
/// which then goes to `sink`. Progress counts the members handed to `sink`; no chunk starts once the
/// control's stop holds (held primaries are then left out). Statistics: the device's seconds, the host's
/// fill, wait and delivery.
SweepOutcome run_row_chunks(const Scene& scene, const VariantRange& range, const SlotSchedule& schedule,
                            std::size_t capacity, const RunControl& control, const ResultSink& sink,
                            RowSlotDevice& device);

}  // namespace rotorsweep::ensemble
