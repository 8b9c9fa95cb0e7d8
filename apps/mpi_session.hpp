// An MPI job's session for the commands that run under mpirun (`run`, `slider`): init and finalize,
// rank and size, broadcasts from rank 0, the shared counters the ranks claim members from, the output's
// checks, the file each rank streams its members into.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>

#include "commands.hpp"
#include "io/output_target.hpp"
#include "rank_files.hpp"

namespace rotorsweep::apps {

/// MPI from construction to destruction; threads call MPI one at a time (MPI_THREAD_SERIALIZED).
class MpiSession {
 public:
  MpiSession() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiSession() { MPI_Finalize(); }
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }
  /// Rank 0's value of `value`, on every rank.
  int broadcast(int value) const {
    MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
    return value;
  }
  std::string broadcast(std::string text) const {
    int length = int(text.size());
    MPI_Bcast(&length, 1, MPI_INT, 0, MPI_COMM_WORLD);
    text.resize(std::size_t(length));
    MPI_Bcast(text.data(), length, MPI_CHAR, 0, MPI_COMM_WORLD);
    return text;
  }

 private:
  int rank_ = 0, size_ = 1;
};

/// Counters in a window on rank 0 (one per variant of a run, per group of a slider scan); every rank's
/// threads fetch-and-add them: the ranks' dynamic share of a plan.
class SharedCounters {
 public:
  SharedCounters(std::size_t count, int rank) {
    const MPI_Aint bytes = rank == 0 ? MPI_Aint(count * sizeof(std::uint64_t)) : 0;
    MPI_Win_allocate(bytes, sizeof(std::uint64_t), MPI_INFO_NULL, MPI_COMM_WORLD, &base_, &window_);
    if (rank == 0)
      for (std::size_t i = 0; i < count; ++i) base_[i] = 0;
    MPI_Barrier(MPI_COMM_WORLD);
    MPI_Win_lock_all(0, window_);
  }
  ~SharedCounters() {
    MPI_Win_unlock_all(window_);
    MPI_Win_free(&window_);
  }
  SharedCounters(const SharedCounters&) = delete;
  SharedCounters& operator=(const SharedCounters&) = delete;

  /// The next value of counter `slot` for this process: taken from rank 0 `block` at a time
  /// (one round trip per block), handed out one at a time.
  std::uint64_t take(std::size_t slot) {
    const std::lock_guard guard(lock_);
    auto& [next, end] = pools_[slot];
    if (next == end) {
      const std::uint64_t count = block;
      MPI_Fetch_and_op(&count, &next, MPI_UINT64_T, 0, MPI_Aint(slot), MPI_SUM, window_);
      MPI_Win_flush(0, window_);
      end = next + block;
    }
    return next++;
  }

  /// Members per round trip: a few lane refills' worth, small against a rank's share.
  static constexpr std::uint64_t block = 32;

 private:
  std::map<std::size_t, std::pair<std::uint64_t, std::uint64_t>> pools_;  ///< per slot: [next, end)
  std::uint64_t* base_ = nullptr;
  MPI_Win window_ = MPI_WIN_NULL;
  std::mutex lock_;
};

/// Rank 0 checks the output before any work: no --resume or --shard under mpirun, `path` writable,
/// no partial file of an earlier run (unless --force), and `fits_on_disk(partial)`; every rank gets
/// `partial` and the exit status (0: go on).
int prepare_mpi_output(const MpiSession& mpi, const SceneCommandOptions& options, bool resume,
                       const std::string& shard, const std::string& path,
                       std::optional<io::OutputTarget>& target, std::string& partial,
                       const std::function<bool(const std::string&)>& fits_on_disk);

}  // namespace rotorsweep::apps
