// The end of a run under mpirun (apps/mpi_join.hpp): reductions over the ranks, rank 0's join of their
// files, the output committed or kept partial, and one exit code for every rank.
#include "mpi_join.hpp"

#include <mpi.h>

#include <csignal>
#include <cstdio>
#include <iostream>
#include <vector>

#include "progress_line.hpp"
#include "run_support.hpp"

namespace rotorsweep::apps {

int end_mpi_run(const MpiSession& mpi, MpiRankEnd rank, io::OutputTarget* target, const std::string& path,
                const std::string& partial, std::size_t members, const std::string& command,
                const SceneCommandOptions& options, const std::string& note, const MpiJoin& join) {
  if (!rank.error.empty()) std::fprintf(stderr, "error: rank %d: %s\n", mpi.rank(), rank.error.c_str());
  int failed = rank.error.empty() ? 0 : 1;
  MPI_Allreduce(MPI_IN_PLACE, &failed, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &rank.signal_number, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &rank.wall, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &rank.threads, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  int code = 0;
  if (mpi.rank() == 0) {
    try {
      join.open();
      target->claim_temporary();
      std::size_t joined = 0;
      std::string shares;
      for (int r = 0; r < mpi.size(); ++r) {
        const std::size_t taken = join.join(r);
        joined += taken;
        shares += (r ? ", " : "") + std::to_string(taken);
      }
      if (joined == members && !failed) {
        join.finish(rank.wall, rank.threads);
        target->commit();
        std::fprintf(stderr, "wrote %s: %zu members in %s (members per rank: %s%s)\n", path.c_str(), members,
                     format_duration(rank.wall).c_str(), shares.c_str(), note.c_str());
      } else {
        join.keep_partial(joined, rank.wall, rank.threads);
        target->keep();
        std::fprintf(stderr,
                     "%s: %zu of %zu members done (per rank: %s), kept in %s (complete = FALSE).\n"
                     "resume with: %s\n",
                     failed ? "error: a rank failed" : "stopped", joined, members, shares.c_str(),
                     partial.c_str(), resume_command(command, options, "").c_str());
        code = failed ? 1 : 128 + (rank.signal_number ? rank.signal_number : SIGINT);
      }
    } catch (const std::exception& e) {
      std::cerr << "error: joining the ranks' files into " << partial << " failed: " << e.what() << "\n";
      target->keep();
      code = 1;
    }
  }
  return mpi.broadcast(code);
}

}  // namespace rotorsweep::apps
