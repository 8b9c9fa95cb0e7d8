// What the commands that run under mpirun share before their ranks start: rank 0 checks the output
// path, a partial file left by an earlier run and the disk, and every rank learns the outcome.
#include "mpi_session.hpp"

#include <filesystem>
#include <iostream>

namespace rotorsweep::apps {

int prepare_mpi_output(const MpiSession& mpi, const SceneCommandOptions& options, bool resume,
                       const std::string& shard, const std::string& path,
                       std::optional<io::OutputTarget>& target, std::string& partial,
                       const std::function<bool(const std::string&)>& fits_on_disk) {
  const bool root = mpi.rank() == 0;
  if (resume || !shard.empty()) {
    if (root)
      std::cerr
          << "error: --resume and --shard run in one process; under mpirun the ranks share the whole plan "
             "(resume an MPI run's partial file without mpirun)\n";
    return 2;
  }
  int status = 0;
  if (root) {
    try {
      target.emplace(path, std::vector<std::string>{options.scene}, io::Replaceable::hdf5, options.force,
                     true);
      partial = target->temporary();
      const auto ranks = rank_files(partial);
      if (!options.force && (std::filesystem::exists(partial) || !ranks.empty())) {
        std::cerr
            << "error: " << (std::filesystem::exists(partial) ? partial : ranks.front())
            << " holds the finished members of an earlier run: continue it with --resume (without mpirun), "
               "or start afresh with --force\n";
        target->keep();
        status = 2;
      } else if (!fits_on_disk(partial)) {
        status = 2;
      }
    } catch (const std::exception& e) {
      std::cerr << "error: " << e.what() << " (-o or output.path)\n";
      status = 2;
    }
  }
  if (root && status == 0 && options.force)  // a fresh start: an earlier run's rank files go
    for (const auto& rank : rank_files(partial)) std::filesystem::remove(rank);
  partial = mpi.broadcast(partial);
  return mpi.broadcast(status);
}

}  // namespace rotorsweep::apps
