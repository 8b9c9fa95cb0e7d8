// `mpirun -np K rotorsweep slider SCENE`: the ranks take members from one counter per group of the plan
// on rank 0 (as `run` does per variant), stream them into a file each, and rank 0 joins the rows.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <vector>

#include "build_info.hpp"
#include "ensemble/engine/instruction_set.hpp"
#include "ensemble/gpu/gpu_executor.hpp"
#include "io/member_stream.hpp"
#include "io/slider_result_file.hpp"
#include "mpi_join.hpp"
#include "mpi_session.hpp"
#include "progress_line.hpp"
#include "run_support.hpp"

namespace rotorsweep::apps {

int run_slider_mpi(const SliderOptions& options, const ensemble::SliderScene& scene, int threads) {
  MpiSession mpi;
  const bool root = mpi.rank() == 0;
  const std::string path = output_path(options, scene.output_path, std::nullopt);
  std::optional<io::OutputTarget> target;
  std::string partial;
  const double row_bytes =
      1 + io::table_row_bytes(io::slider_columns(scene, ensemble::slider_timeline(scene)));
  if (const int status = prepare_mpi_output(
          mpi, options, options.resume, options.shard, path, target, partial,
          [&](const std::string& at) {
            const double members = double(scene.member_count());
            return fits_on_disk(2 * members * row_bytes + io::SliderResultFile::finishing_bytes(scene, false),
                                "the results of the ranks' files and the joined file", at,
                                "Split the scan (fewer separations or replicas)");
          });
      status != 0)
    return status;

  const io::Provenance provenance{options.scene, version, revision, ensemble::slider_device_label(scene),
                                  ensemble::instruction_set().name};
  std::vector<std::size_t> plan(scene.member_count());
  for (std::size_t i = 0; i < plan.size(); ++i) plan[i] = i;
  std::string error;
  double wall = 0;
  int signal_number = 0;
  {
    SharedCounters counters(plan.size(), mpi.rank());  // one per group, at the group's first position
    if (root) {
      print_slider_header(options, scene, threads, std::nullopt);
      std::fprintf(stderr, "MPI: %d ranks share the plan\n", mpi.size());
    }
    ProgressLine progress(plan.size(), root && !options.quiet);
    std::mutex progress_lock;
    const auto claim = [&](std::size_t begin, std::size_t end) {
      const std::size_t k = begin + counters.take(begin);
      if (root && progress_lock.try_lock()) {
        progress.update(std::min(k, end));  // members taken by all ranks, groups in plan order
        progress_lock.unlock();
      }
      return k;
    };
    const StopOnSignals signals;
    const auto start = std::chrono::steady_clock::now();
    try {
      const io::SliderResultFile file(rank_file(partial, mpi.rank()), scene, provenance);
      io::SliderMemberStream stream(file, [&signals] { signals.stop(); });
      try {
        ensemble::run_slider_members(
            scene, plan, {.threads = threads, .stop = [&] { return signals.stopped(); }, .claim = claim},
            [&stream](std::vector<ensemble::SliderMember>&& block) { stream.add(std::move(block)); },
            ensemble::device_for(scene.device));
      } catch (const std::bad_alloc&) {
        error = "out of memory (an allocation in a worker thread failed)";
      } catch (const std::exception& e) {
        error = e.what();
      }
      stream.flush();  // what the scan finished before it failed, or the write's error
    } catch (const std::exception& e) {
      if (error.empty()) error = e.what();
    }
    wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    signal_number = signals.signal();
    MPI_Barrier(MPI_COMM_WORLD);
    progress.finish();
  }
  std::optional<io::SliderResultFile> out;
  return end_mpi_run(mpi, {error, signal_number, wall, threads}, target ? &*target : nullptr, path, partial,
                     scene.member_count(), "slider", options, "",
                     {[&] { out.emplace(partial, scene, provenance); },
                      [&](int r) {
                        const std::string from = rank_file(partial, r);
                        return std::filesystem::exists(from) ? join_rank_file(*out, scene, from) : 0;
                      },
                      [&](double all_wall, int all_threads) {
                        out->finish(all_wall, all_threads);
                        out->close();
                      },
                      [&](std::size_t joined, double all_wall, int all_threads) {
                        out->keep_partial(joined, all_wall, all_threads);
                        out->close();
                      }});
}

}  // namespace rotorsweep::apps
