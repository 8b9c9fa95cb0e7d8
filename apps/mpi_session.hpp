// An MPI job's session for the commands that run under mpirun (`run`, `slider`): init and finalize,
// rank and size, broadcasts from rank 0, the output's checks, the file each rank streams its members into.
#pragma once

#include <mpi.h>

#include <functional>
#include <optional>
#include <string>

#include "commands.hpp"
#include "io/output_target.hpp"

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

/// The file rank `rank` streams its members into, beside the run's partial file.
inline std::string rank_file(const std::string& partial, int rank) {
  return partial + ".rank-" + std::to_string(rank);
}

/// Rank 0 checks the output before any work: no --resume or --shard under mpirun, `path` writable,
/// no partial file of an earlier run (unless --force), and `fits_on_disk(partial)`; every rank gets
/// `partial` and the exit status (0: go on).
int prepare_mpi_output(const MpiSession& mpi, const SceneCommandOptions& options, bool resume,
                       const std::string& shard, const std::string& path,
                       std::optional<io::OutputTarget>& target, std::string& partial,
                       const std::function<bool(const std::string&)>& fits_on_disk);

}  // namespace rotorsweep::apps
