// The GPU sweep of one variant: a persistent grid whose threads each take the next member from a
// counter (refill) and run it with DeviceMember<Model, Integrator>; the host fills and reads chunks
// of member slots.
#pragma once

#include <cuda_runtime.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include "ensemble/engine/member_slots.hpp"
#include "ensemble/gpu/device_drivers.hpp"
#include "ensemble/gpu/gpu_backend.hpp"

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

/// One chunk's device buffers (SlotChunk::buffers() order) and its member counter.
class DeviceChunk {
 public:
  explicit DeviceChunk(SlotChunk& host) {
    for (const auto& b : host.buffers()) {
      void* p = nullptr;
      check(cudaMalloc(&p, std::max<std::size_t>(b.bytes, 8)), "allocating member slots");
      pointers_.push_back(p);
    }
    check(cudaMalloc(&counter_, sizeof(unsigned long long)), "allocating the member counter");
  }
  DeviceChunk(const DeviceChunk&) = delete;
  DeviceChunk& operator=(const DeviceChunk&) = delete;
  ~DeviceChunk() {
    for (void* p : pointers_) cudaFree(p);
    cudaFree(counter_);
  }
  SlotViews views() const { return slot_views(pointers_.data()); }
  unsigned long long* counter() const { return counter_; }

  void upload(SlotChunk& host, cudaStream_t stream) {
    const auto buffers = host.buffers();
    for (std::size_t i = 0; i < buffers.size(); ++i)
      if (buffers[i].input)
        check(
            cudaMemcpyAsync(pointers_[i], buffers[i].data, buffers[i].bytes, cudaMemcpyHostToDevice, stream),
            "copying member inputs");
    check(cudaMemsetAsync(counter_, 0, sizeof(unsigned long long), stream), "resetting the member counter");
  }
  void download(SlotChunk& host, cudaStream_t stream) {
    const auto buffers = host.buffers();
    for (std::size_t i = 0; i < buffers.size(); ++i)
      if (!buffers[i].input)
        check(
            cudaMemcpyAsync(buffers[i].data, pointers_[i], buffers[i].bytes, cudaMemcpyDeviceToHost, stream),
            "copying member results");
  }

 private:
  std::vector<void*> pointers_;
  unsigned long long* counter_ = nullptr;
};

/// The variant's members in chunks: while the GPU runs one chunk, the host fills the next and
/// summarizes the last. Stops between chunks when control.stop is raised.
template <class Model, class Integrator>
SweepOutcome run_slots(const Scene& scene, const VariantRange& range, int host_threads,
                       const SweepControl& control, const ResultSink& sink) {
  using Driver = DeviceMember<Model, Integrator>;
  const GpuInfo& info = gpu_info();
  if (!info.available) throw std::runtime_error("numerics.device = \"gpu\": " + info.why);
  const Member variant = range.source->at(range.begin);
  const SlotSchedule schedule = slot_schedule(scene, variant, device_first_step_scale<Integrator>(variant));
  if (Driver::storage_size(schedule) > gpu_thread_scratch)
    throw std::runtime_error("model.rows = " + std::to_string(variant.rows) +
                             " is more than the GPU backend holds (" + std::to_string(gpu_max_rows(scene)) +
                             " rows with this scene's model and stepper)");

  const auto kernel = sweep_slots<Model, Integrator>;
  const GpuLaunch launch = gpu_launch();
  int blocks = launch.blocks;
  if (blocks <= 0) {
    int per_multiprocessor = 0;
    check(cudaOccupancyMaxActiveBlocksPerMultiprocessor(&per_multiprocessor, kernel, launch.threads_per_block,
                                                        0),
          "sizing the grid");
    blocks = std::max(1, per_multiprocessor) * info.multiprocessors;
  }
  const std::size_t resident = std::size_t(blocks) * std::size_t(launch.threads_per_block);
  const std::size_t members = range.end - range.begin;
  const std::size_t chunk = std::min(members, std::max<std::size_t>(8 * resident, 1 << 16));

  SweepOutcome outcome;
  auto& stats = outcome.statistics;
  stats.threads = int(resident);
  stats.lane_width = 1;
  const auto start = std::chrono::steady_clock::now();
  std::array<SlotChunk, 2> host{SlotChunk(schedule, chunk), SlotChunk(schedule, chunk)};
  DeviceChunk device0(host[0]), device1(host[1]);
  std::array<DeviceChunk*, 2> device{&device0, &device1};
  cudaStream_t stream = nullptr;
  check(cudaStreamCreate(&stream), "creating a stream");

  const auto launch_chunk = [&](std::size_t b, std::size_t first) {
    const std::size_t count = std::min(chunk, range.end - first);
    host[b].fill(scene, range, first, count);
    device[b]->upload(host[b], stream);
    kernel<<<blocks, launch.threads_per_block, 0, stream>>>(schedule, device[b]->views(), count,
                                                            device[b]->counter());
    check(cudaGetLastError(), "launching the sweep kernel");
    device[b]->download(host[b], stream);
  };
  std::size_t done = 0;
  try {
    launch_chunk(0, range.begin);
    for (std::size_t first = range.begin, b = 0; first < range.end; first += chunk, b ^= 1) {
      check(cudaStreamSynchronize(stream), "running the sweep kernel");
      const std::size_t next = first + chunk;
      if (next < range.end && !control.stopped()) launch_chunk(b ^ 1, next);
      const double attempts = host[b].deliver(scene, host_threads, sink);
      stats.lane_steps_busy += attempts;
      stats.lane_steps_total += attempts;
      done += host[b].count();
      if (control.progress) control.progress(done);
      if (control.stopped()) break;
    }
    check(cudaStreamSynchronize(stream), "running the sweep kernel");
  } catch (...) {
    cudaStreamSynchronize(stream);
    cudaStreamDestroy(stream);
    throw;
  }
  cudaStreamDestroy(stream);
  stats.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.interrupted = control.stopped();
  return outcome;
}

}  // namespace rotorsweep::ensemble::gpu
