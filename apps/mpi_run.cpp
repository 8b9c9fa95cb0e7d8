// `mpirun -np K rotorsweep run SCENE`: the ranks take members from one counter per variant on rank 0
// (MPI one-sided fetch-and-add), stream them into a file each, and rank 0 joins the rows.
#include <mpi.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>

#include "build_info.hpp"
#include "ensemble/engine/instruction_set.hpp"
#include "ensemble/gpu/gpu_executor.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/member_stream.hpp"
#include "io/output_target.hpp"
#include "io/result_reader.hpp"
#include "mpi_join.hpp"
#include "mpi_session.hpp"
#include "progress_line.hpp"
#include "run_needs.hpp"
#include "run_support.hpp"

namespace rotorsweep::apps {

bool launched_by_mpi() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMIX_RANK") != nullptr ||
         std::getenv("PMI_RANK") != nullptr;
}

int run_sweep_mpi(const RunOptions& options, const ensemble::Scene& scene, int threads) {
  MpiSession mpi;
  const bool root = mpi.rank() == 0;
  const std::string path = output_path(options, scene.output_path, std::nullopt);
  std::optional<io::OutputTarget> target;
  std::string partial;
  if (const int status = prepare_mpi_output(
          mpi, options, options.resume, options.shard, path, target, partial,
          [&](const std::string& at) { return !refused(sweep_disk_refusal(scene, scene.member_count(), false, at)); });
      status != 0)
    return status;

  // every rank: the members it takes, streamed into a whole-plan file of its own
  const ensemble::MemberPlan plan(scene);
  const io::Provenance provenance{options.scene, version, revision, ensemble::device_label(scene),
                                  ensemble::instruction_set().name};
  std::string error;
  ensemble::SweepOutcome outcome;
  int signal_number = 0;
  {
    const StopOnSignals signals;  // before the rank's file: a signal from now on stops the run, keeping it
    std::optional<io::ResultFile> file;
    try {
      file.emplace(rank_file(partial, mpi.rank()), scene, provenance);
    } catch (const std::exception& e) {
      error = e.what();
    }
    SharedCounters counters(scene.variants().size(), mpi.rank());
    if (root) print_header(options, scene, plan.size(), threads, std::nullopt);
    if (root) std::fprintf(stderr, "MPI: %d ranks share the plan\n", mpi.size());
    ProgressLine progress(plan.size(), root && !options.quiet);
    std::mutex progress_lock;
    const ensemble::MemberSource source{plan.size(), [&](std::size_t k) { return plan[k]; }};
    const auto claim = [&](std::size_t begin, std::size_t) {
      const std::size_t k = begin + counters.take(plan[begin].variant);
      if (root && progress_lock.try_lock()) {
        progress.update(std::min(k, plan.size()));  // members taken by all ranks
        progress_lock.unlock();
      }
      return k;
    };
    if (file) {
      io::MemberStream stream(*file, plan, {options.flush_seconds, options.flush_members},
                              [&signals] { signals.stop(); });
      outcome = ensemble::run_members(
          scene, source, {.threads = threads, .stop = [&] { return signals.stopped(); }, .claim = claim},
          [&stream](ensemble::MemberResult&& r) { stream.add(std::move(r)); }, ensemble::device_for(scene.device));
      try {
        stream.flush();
        file->keep_partial(stream.written(), outcome.statistics);
        file->close();
      } catch (const std::exception& e) {
        error = e.what();
      }
    }
    signal_number = signals.signal();
    MPI_Barrier(MPI_COMM_WORLD);  // every rank is done with the counters
    progress.finish();
  }
  // the run's statistics over all ranks (end_mpi_run takes the wall time's maximum and the threads' sum)
  auto stats = outcome.statistics;
  double busy = stats.lane_steps_busy, total = stats.lane_steps_total;
  MPI_Allreduce(MPI_IN_PLACE, &busy, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  stats.lane_steps_busy = busy;
  stats.lane_steps_total = total;
  char occupancy[64];
  std::snprintf(occupancy, sizeof occupancy, "; lane occupancy %.1f %%", 100 * stats.occupancy());

  std::optional<io::ResultFile> out;
  const auto with_totals = [&stats](double wall, int threads) {
    stats.wall_seconds = wall;
    stats.threads = threads;
    return stats;
  };
  return end_mpi_run(mpi, {error, signal_number, stats.wall_seconds, stats.threads},
                     target ? &*target : nullptr, path, partial, plan.size(), "run", options, occupancy,
                     {[&] { out.emplace(partial, scene, provenance); },
                      [&](int r) { return join_rank_file(*out, scene, rank_file(partial, r)); },
                      [&](double wall, int threads) {
                        out->finish(with_totals(wall, threads));
                        out->close();
                        report_outcome(io::Hdf5Location::open_file(partial), scene);
                      },
                      [&](std::size_t joined, double wall, int threads) {
                        out->keep_partial(joined, with_totals(wall, threads));
                        out->close();
                      }});
}

}  // namespace rotorsweep::apps
