// The GPU sweep of one variant: a persistent grid whose threads, or teams of a warp's threads, each
// take the next member from a counter (refill) and run it with DeviceMember, TeamMember or
// SliderTeamMember; the host fills and reads chunks of member slots.
#pragma once

#include <cuda_runtime.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "ensemble/engine/member_forms.hpp"
#include "ensemble/gpu/device_drivers.hpp"
#include "ensemble/gpu/gpu_backend.hpp"
#include "ensemble/gpu/gpu_executor.hpp"
#include "ensemble/gpu/gpu_plan.hpp"
#include "ensemble/rows/member_slots.hpp"
#include "ensemble/rows/row_chunks.hpp"
#include "ensemble/rows/team_member.hpp"
#include "kernels/lanes/team.hpp"

namespace rotorsweep::ensemble::gpu {

/// Throws with the CUDA error's text where `status` is not cudaSuccess.
inline void check(cudaError_t status, const char* what) {
  if (status != cudaSuccess)
    throw std::runtime_error(std::string("GPU: ") + what + ": " + cudaGetErrorString(status));
}

/// A thread's scratch is an array in local memory, which the GPU interleaves across a warp's
/// threads: the same offset in every thread is one coalesced access.
template <class Model, class Integrator>
__global__ void sweep_slots(SlotSchedule schedule, SlotViews slots, unsigned long long count,
                            unsigned long long* next) {
  double storage[gpu_thread_scratch];
  for (;;) {
    const unsigned long long k = atomicAdd(next, 1ull);
    if (k >= count) return;
    DeviceMember<Model, Integrator>::run(schedule, slots, std::size_t(k), storage, gpu_thread_scratch);
  }
}

/// A member per team of `team` threads of a warp (WarpTeam; Driver<const WarpTeam, TeamIntegrator>:
/// TeamMember, SliderTeamMember). The team's first thread takes the next member from the counter for
/// all; the team's scratch is its part of the block's shared memory or, where `scratch` is given, of
/// that global buffer (per_team values each).
template <template <class, class> class Driver, class TeamIntegrator, class Schedule, class Views>
__global__ void sweep_slots_on_teams(const __grid_constant__ Schedule schedule, Views slots,
                                     unsigned long long count, unsigned long long* next, unsigned team,
                                     double* scratch, std::size_t per_team) {
  extern __shared__ double shared_scratch[];
  const std::size_t teams = blockDim.x / team, mine = threadIdx.x / team;
  const kernels::WarpTeam crew(team);
  double* storage = scratch ? scratch + (std::size_t(blockIdx.x) * teams + mine) * per_team
                            : shared_scratch + mine * per_team;
  for (;;) {
    const unsigned long long k = crew.first([&] { return atomicAdd(next, 1ull); });
    if (k >= count) return;
    Driver<const kernels::WarpTeam, TeamIntegrator>::run(crew, schedule, slots, std::size_t(k), storage,
                                                         per_team);
    crew.sync();
  }
}

/// A buffer of device memory, freed with its owner.
class DeviceBuffer {
 public:
  DeviceBuffer(std::size_t bytes, const char* what) {
    check(cudaMalloc(&data_, std::max<std::size_t>(bytes, 8)), what);
  }
  DeviceBuffer(const DeviceBuffer&) = delete;
  DeviceBuffer& operator=(const DeviceBuffer&) = delete;
  ~DeviceBuffer() { cudaFree(data_); }
  void* data() const { return data_; }

 private:
  void* data_ = nullptr;
};

/// One chunk's device buffers (Chunk::buffers() order: SlotChunk, SliderSlotChunk), their pinned host
/// copies (so that copies run beside kernels and the host) and its member counter; views_of makes the
/// chunk's views of the device buffers. upload copies the host chunk's inputs and queues them;
/// download queues the outputs, which take_results copies into the host chunk once they have arrived.
template <class Chunk, auto views_of>
class DeviceChunk {
 public:
  explicit DeviceChunk(Chunk& host) {
    for (const auto& b : host.buffers()) {
      void* p = nullptr;
      check(cudaMalloc(&p, std::max<std::size_t>(b.bytes, 8)), "allocating member slots");
      pointers_.push_back(p);
      void* pinned = nullptr;
      check(cudaMallocHost(&pinned, std::max<std::size_t>(b.bytes, 8)), "allocating pinned member slots");
      pinned_.push_back(pinned);
    }
    check(cudaMalloc(&counter_, sizeof(unsigned long long)), "allocating the member counter");
  }
  DeviceChunk(const DeviceChunk&) = delete;
  DeviceChunk& operator=(const DeviceChunk&) = delete;
  ~DeviceChunk() {
    for (void* p : pointers_) cudaFree(p);
    for (void* p : pinned_) cudaFreeHost(p);
    cudaFree(counter_);
  }
  auto views() const { return views_of(pointers_.data()); }
  unsigned long long* counter() const { return counter_; }

  void upload(Chunk& host, cudaStream_t stream) {
    const auto buffers = host.buffers();
    for (std::size_t i = 0; i < buffers.size(); ++i)
      if (buffers[i].input) {
        std::memcpy(pinned_[i], buffers[i].data, buffers[i].bytes);
        check(cudaMemcpyAsync(pointers_[i], pinned_[i], buffers[i].bytes, cudaMemcpyHostToDevice, stream),
              "copying member inputs");
      }
    check(cudaMemsetAsync(counter_, 0, sizeof(unsigned long long), stream), "resetting the member counter");
  }
  void download(Chunk& host, cudaStream_t stream) {
    const auto buffers = host.buffers();
    for (std::size_t i = 0; i < buffers.size(); ++i)
      if (!buffers[i].input)
        check(cudaMemcpyAsync(pinned_[i], pointers_[i], buffers[i].bytes, cudaMemcpyDeviceToHost, stream),
              "copying member results");
  }
  /// After the download has completed.
  void take_results(Chunk& host) const {
    const auto buffers = host.buffers();
    for (std::size_t i = 0; i < buffers.size(); ++i)
      if (!buffers[i].input) std::memcpy(buffers[i].data, pinned_[i], buffers[i].bytes);
  }

 private:
  std::vector<void*> pointers_, pinned_;
  unsigned long long* counter_ = nullptr;
};

/// The device executor's two chunk slots on one stream, for any problem's chunk layout (Chunk, views_of
/// as DeviceChunk's), driven by run_chunks_two_in_flight: start(host, slot, launch) queues the host
/// chunk's inputs, its kernel (launch(stream, views, count, counter)) and the copy of its outputs;
/// finish(host, slot) waits for them, puts them into the host chunk and returns the kernel's seconds
/// (CUDA events). A slot's buffers are allocated at its first start, again after reset() (a layout of
/// another size: the slider's next size and speed); a slot never started allocates nothing.
template <class Chunk, auto views_of>
class ChunkStream {
 public:
  ChunkStream() {
    check(cudaStreamCreate(&stream_), "creating a stream");
    for (cudaEvent_t& e : events_) check(cudaEventCreate(&e), "creating an event");
  }
  ChunkStream(const ChunkStream&) = delete;
  ChunkStream& operator=(const ChunkStream&) = delete;
  ~ChunkStream() {
    cudaStreamSynchronize(stream_);
    slots_ = {};
    for (cudaEvent_t e : events_) cudaEventDestroy(e);
    cudaStreamDestroy(stream_);
  }

  /// Waits for both slots and frees their buffers.
  void reset() {
    check(cudaStreamSynchronize(stream_), "running the sweep kernel");
    slots_ = {};
  }

  template <class Launch>
  void start(Chunk& host, std::size_t slot, Launch&& launch) {
    if (!slots_[slot]) slots_[slot] = std::make_unique<DeviceChunk<Chunk, views_of>>(host);
    DeviceChunk<Chunk, views_of>& device = *slots_[slot];
    device.upload(host, stream_);
    check(cudaEventRecord(events_[3 * slot], stream_), "timing the sweep kernel");
    launch(stream_, device.views(), (unsigned long long)host.count(), device.counter());
    check(cudaGetLastError(), "launching the sweep kernel");
    check(cudaEventRecord(events_[3 * slot + 1], stream_), "timing the sweep kernel");
    device.download(host, stream_);
    check(cudaEventRecord(events_[3 * slot + 2], stream_), "copying member results");
  }

  double finish(Chunk& host, std::size_t slot) {
    check(cudaEventSynchronize(events_[3 * slot + 2]), "running the sweep kernel");
    float kernel_ms = 0.0f;
    check(cudaEventElapsedTime(&kernel_ms, events_[3 * slot], events_[3 * slot + 1]),
          "timing the sweep kernel");
    slots_[slot]->take_results(host);
    return 1e-3 * double(kernel_ms);
  }

 private:
  cudaStream_t stream_ = nullptr;
  std::array<cudaEvent_t, 6> events_{};  // per slot: its kernel's start and end, its results arrived
  std::array<std::unique_ptr<DeviceChunk<Chunk, views_of>>, 2> slots_;
};

/// How one chunk's kernel is launched: the grid, each block's dynamic shared memory, and how many
/// members run at once (threads, or teams).
struct ChunkGrid {
  int blocks = 0, threads_per_block = 0;
  std::size_t shared_bytes = 0;
  std::size_t resident = 0;
};

/// The blocks that fit on the GPU at once for `kernel` (or plan.blocks where set).
template <class Kernel>
int resident_blocks(Kernel kernel, const GpuPlan& plan, std::size_t shared_bytes) {
  if (plan.blocks > 0) return plan.blocks;
  int per_multiprocessor = 0;
  check(cudaOccupancyMaxActiveBlocksPerMultiprocessor(&per_multiprocessor, kernel, plan.threads_per_block,
                                                      shared_bytes),
        "sizing the grid");
  return std::max(1, per_multiprocessor) * gpu_info().multiprocessors;
}

/// The GPU as a RowSlotDevice: a ChunkStream whose chunks run launch(stream, schedule, views, count,
/// counter), the chunk's schedule (a plan's or its shadow runs') as the kernel's argument.
template <class Launch>
class GpuRowDevice final : public RowSlotDevice {
 public:
  explicit GpuRowDevice(Launch& launch) : launch_(launch) {}
  void start(SlotChunk& chunk, std::size_t slot) override {
    stream_.start(
        chunk, slot,
        [&](cudaStream_t stream, const SlotViews& views, unsigned long long count,
            unsigned long long* counter) { launch_(stream, chunk.schedule(), views, count, counter); });
  }
  double finish(SlotChunk& chunk, std::size_t slot) override { return stream_.finish(chunk, slot); }

 private:
  Launch& launch_;
  ChunkStream<SlotChunk, slot_views> stream_;
};

/// The variant's members on the GPU with `launch` (GpuRowDevice) through run_row_chunks, in chunks of the
/// plan's size (GpuPlan::chunk_members); the stream's and events' creation counts as set-up.
template <class Launch>
SweepOutcome run_chunks(const Scene& scene, const VariantRange& range, const SlotSchedule& schedule,
                        const ChunkGrid& grid, const GpuPlan& plan, const RunControl& control,
                        const ResultSink& sink, Launch&& launch) {
  const auto start = std::chrono::steady_clock::now();
  const std::size_t chunk = plan.chunk_members(grid.resident, range.end - range.begin);
  GpuRowDevice device(launch);
  const double setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  SweepOutcome outcome = run_row_chunks(scene, range, schedule, chunk, control, sink, device);
  outcome.statistics.threads = grid.blocks * grid.threads_per_block;
  outcome.statistics.setup_seconds += setup;
  outcome.statistics.wall_seconds += setup;
  return outcome;
}

/// The GPU's description, or an error where there is none.
inline const GpuInfo& available_gpu() {
  const GpuInfo& info = gpu_info();
  if (!info.available) throw std::runtime_error("numerics.device = \"gpu\": " + info.why);
  use_gpu();
  return info;
}

/// The variant's members, one per thread (DeviceMember<Model, Integrator>, the CPU lanes' bits).
template <class Model, class Integrator>
SweepOutcome run_slots(const Scene& scene, const VariantRange& range, const GpuPlan& plan,
                       const RunControl& control, const ResultSink& sink) {
  using Driver = DeviceMember<Model, Integrator>;
  static_assert(ThreadMemberForm<Driver, SlotSchedule, SlotViews>);
  available_gpu();
  const Member variant = range.source->at(range.begin);
  const SlotSchedule schedule =
      slot_schedule(scene, variant, device_first_step_scale<Integrator>(scene, variant));
  if (Driver::storage_size(schedule) > gpu_thread_scratch) {
    const std::size_t per_thread = GpuExecutor(GpuLaunch{.team = 1}).max_rows(scene);  // a thread's limit
    throw std::runtime_error("model.rows = " + std::to_string(variant.rows) +
                             " is more than the GPU backend holds (" + std::to_string(per_thread) +
                             " rows with this scene's model and stepper on one thread each)");
  }

  const auto kernel = sweep_slots<Model, Integrator>;
  ChunkGrid grid{resident_blocks(kernel, plan, 0), plan.threads_per_block, 0, 0};
  grid.resident = std::size_t(grid.blocks) * std::size_t(grid.threads_per_block);
  return run_chunks(scene, range, schedule, grid, plan, control, sink,
                    [&](cudaStream_t stream, const SlotSchedule& chunk_schedule, const SlotViews& views,
                        unsigned long long count, unsigned long long* counter) {
                      kernel<<<grid.blocks, grid.threads_per_block, 0, stream>>>(chunk_schedule, views, count,
                                                                                 counter);
                    });
}

/// How teams of plan.team threads are launched with `kernel` (a sweep_slots_on_teams) when each keeps
/// `per_team` values of scratch: a block's teams in its shared memory where they fit and the plan puts
/// them there (GpuPlan::scratch), else in `scratch`, a global buffer of which the resident teams take at
/// most a quarter of the GPU's memory; shared memory that the plan was asked for and that does not fit
/// is an error.
struct TeamLaunch {
  ChunkGrid grid;
  std::size_t per_team = 0;
  std::unique_ptr<DeviceBuffer> scratch;  ///< with global scratch
  double* global() const { return scratch ? static_cast<double*>(scratch->data()) : nullptr; }
};
template <class Kernel>
TeamLaunch team_launch(Kernel kernel, const GpuPlan& plan, std::size_t per_team) {
  const GpuInfo& info = available_gpu();
  const std::size_t teams_per_block = std::size_t(plan.threads_per_block) / plan.team;
  const std::size_t block_bytes = teams_per_block * per_team * sizeof(double);
  int shared_limit = 0;
  check(cudaDeviceGetAttribute(&shared_limit, cudaDevAttrMaxSharedMemoryPerBlockOptin, 0),
        "querying the shared memory");
  const bool fits = block_bytes <= std::size_t(shared_limit);
  if (plan.scratch_asked && plan.scratch == GpuScratch::shared && !fits)
    throw std::runtime_error("ROTORSWEEP_GPU_SCRATCH = shared: a block's " + std::to_string(teams_per_block) +
                             " teams need " + std::to_string(block_bytes / 1024) + " KiB, more than the " +
                             std::to_string(shared_limit / 1024) +
                             " KiB of shared memory a block has; use fewer threads per block "
                             "(ROTORSWEEP_GPU_BLOCK) or global");
  const bool shared = fits && plan.scratch == GpuScratch::shared;
  const std::size_t shared_bytes = shared ? block_bytes : 0;
  check(cudaFuncSetAttribute(kernel, cudaFuncAttributeMaxDynamicSharedMemorySize, int(shared_bytes)),
        "reserving shared memory");

  TeamLaunch out;
  out.per_team = per_team;
  out.grid = {resident_blocks(kernel, plan, shared_bytes), plan.threads_per_block, shared_bytes, 0};
  if (!shared) {
    const double quarter = info.memory_gib * double(1ull << 30) / 4.0;
    out.grid.blocks =
        int(std::max(1.0, std::min(double(out.grid.blocks), std::floor(quarter / double(block_bytes)))));
    out.scratch =
        std::make_unique<DeviceBuffer>(std::size_t(out.grid.blocks) * block_bytes, "allocating team scratch");
  }
  out.grid.resident = std::size_t(out.grid.blocks) * teams_per_block;
  return out;
}

/// The variant's members, one per team of plan.team threads of a warp with TeamIntegrator (TeamMember on
/// const WarpTeam; the schedule's first-step scale is Integrator's, the same integrator on one lane),
/// their scratch where team_launch puts it.
template <class Integrator, class TeamIntegrator>
SweepOutcome run_slots_on_teams(const Scene& scene, const VariantRange& range, const GpuPlan& plan,
                                const RunControl& control, const ResultSink& sink) {
  using Driver = TeamMember<const kernels::WarpTeam, TeamIntegrator>;
  static_assert(TeamMemberForm<Driver, const kernels::WarpTeam, SlotSchedule, SlotViews>);
  const Member variant = range.source->at(range.begin);
  const SlotSchedule schedule =
      slot_schedule(scene, variant, device_first_step_scale<Integrator>(scene, variant));
  if (!Driver::team_schedule_fits(schedule)) throw std::logic_error("a team cannot run this schedule");

  const auto kernel = sweep_slots_on_teams<TeamMember, TeamIntegrator, SlotSchedule, SlotViews>;
  const unsigned team = plan.team;
  const TeamLaunch teams = team_launch(kernel, plan, Driver::storage_size(schedule, team));
  return run_chunks(
      scene, range, schedule, teams.grid, plan, control, sink,
      [&](cudaStream_t stream, const SlotSchedule& chunk_schedule, const SlotViews& views,
          unsigned long long count, unsigned long long* counter) {
        kernel<<<teams.grid.blocks, teams.grid.threads_per_block, teams.grid.shared_bytes, stream>>>(
            chunk_schedule, views, count, counter, team, teams.global(), teams.per_team);
      });
}

/// The variant's members by the plan's mapping: a team per member with TeamIntegrator where the plan says
/// so (void: the stepper has no team form), else a thread per member with Integrator over Model.
template <class Model, class Integrator, class TeamIntegrator>
SweepOutcome run_planned(const Scene& scene, const VariantRange& range, const GpuPlan& plan,
                         const RunControl& control, const ResultSink& sink) {
  if constexpr (!std::is_void_v<TeamIntegrator>)
    if (plan.mapping == GpuMapping::team)
      return run_slots_on_teams<Integrator, TeamIntegrator>(scene, range, plan, control, sink);
  return run_slots<Model, Integrator>(scene, range, plan, control, sink);
}

}  // namespace rotorsweep::ensemble::gpu
