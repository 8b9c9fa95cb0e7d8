// What a run, scan or landscape needs, refused before any work: memory to work in, disk for its file, a GPU.
// Each check returns its refusal in the command line's words; the commands print it (exit 2), the Python
// module raises it as ValueError (RunRefused).
#pragma once

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>

#include "ensemble/engine/device.hpp"
#include "ensemble/rows/scene.hpp"
#include "ensemble/slider/slider_scene.hpp"

namespace rotorsweep::apps {

/// A refusal thrown where the caller cannot return an exit code (the Python module's jobs).
struct RunRefused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Throws RunRefused with the refusal, if there is one.
void throw_refusal(const std::optional<std::string>& refusal);

/// Where `needed` bytes do not fit on the disk of `partial` (95 % of its free space): how much `what`
/// (plural: "the results ... need") needs, what is free there, and `advice`.
std::optional<std::string> disk_refusal(double needed, const std::string& what, const std::string& partial,
                                        const std::string& advice);
/// Where `device` is the GPU and this process has none: why, and to run on the CPU.
std::optional<std::string> gpu_refusal(ensemble::Device device);

/// Where a row sweep's threads' lane blocks, and `held_bytes` more (a result kept in memory), do not fit
/// in 80 % of the memory this process may use.
std::optional<std::string> sweep_memory_refusal(const ensemble::Scene& scene, int threads, double held_bytes = 0);
/// The disk bytes of `rows` members of a row sweep and its file's finishing writes (none in a shard).
double sweep_disk_bytes(const ensemble::Scene& scene, std::size_t rows, bool shard);
/// Where sweep_disk_bytes do not fit on the disk of `partial`.
std::optional<std::string> sweep_disk_refusal(const ensemble::Scene& scene, std::size_t rows, bool shard,
                                              const std::string& partial);

/// Where a CPU scan's threads (each a lane block, substrate tables and its lanes' members' series, two more
/// members' series on their way into the file) do not fit in memory.
std::optional<std::string> scan_memory_refusal(const ensemble::SliderScene& scene, int threads);
/// Where `members` members of a slider scan and its file's finishing writes (none in a shard) do not fit
/// on the disk of `partial`.
std::optional<std::string> scan_disk_refusal(const ensemble::SliderScene& scene, std::size_t members, bool shard,
                                             const std::string& partial);

/// Where a chamber map of A_cells × tau_cells cells (its counts, labels and written fields) does not fit in
/// memory.
std::optional<std::string> chamber_memory_refusal(int A_cells, int tau_cells);
/// Where a curve of `samples` points (and its written columns) does not fit in memory.
std::optional<std::string> curve_memory_refusal(long long samples);

}  // namespace rotorsweep::apps
