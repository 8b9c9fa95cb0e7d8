// The end of a run under mpirun (`run`, `slider`): the ranks agree on failures, stops, wall time and threads,
// and rank 0 joins the ranks' files into the run's output, committed when complete, else kept to resume.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

#include "io/output_target.hpp"
#include "mpi_session.hpp"

namespace rotorsweep::apps {

/// What one rank brings to the end: its failure (empty if none), the signal that stopped it (0 if none),
/// its wall time and threads.
struct MpiRankEnd {
  std::string error;
  int signal_number = 0;
  double wall = 0.0;
  int threads = 0;
};

/// How rank 0 joins the ranks' files (end_mpi_run): open() the joined file at the partial path, join(r)
/// rank r's members into it (its file removed; returns how many), then finish(wall, threads) a complete
/// run (the file closed, its outcome reported) or keep_partial(joined, wall, threads) one that stopped or
/// failed; wall is the slowest rank's, threads the ranks' sum.
struct MpiJoin {
  std::function<void()> open;
  std::function<std::size_t(int rank)> join;
  std::function<void(double wall, int threads)> finish;
  std::function<void(std::size_t joined, double wall, int threads)> keep_partial;
};

/// On every rank after its share: prints this rank's error; rank 0 joins (MpiJoin), commits `target` to
/// `path` when all `members` are there and no rank failed ("wrote PATH: … (members per rank: …`note`)"),
/// else keeps the partial file and names the resume command of `command`. Returns the exit code on every
/// rank: 0, 1 (a rank or the join failed), 128 + the signal (stopped).
int end_mpi_run(const MpiSession& mpi, MpiRankEnd rank, io::OutputTarget* target, const std::string& path,
                const std::string& partial, std::size_t members, const std::string& command,
                const SceneCommandOptions& options, const std::string& note, const MpiJoin& join);

}  // namespace rotorsweep::apps
