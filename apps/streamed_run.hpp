// What `rotorsweep run` and `rotorsweep slider` do alike with a run streamed into its partial file: reopen
// one to resume, run the sweep and flush the writer with their failures caught, end failed, stopped or
// finished.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "ensemble/engine/instruction_set.hpp"
#include "io/hdf5_file.hpp"
#include "io/output_target.hpp"
#include "rank_files.hpp"
#include "run_support.hpp"

namespace rotorsweep::apps {

/// Joins the rank files an mpirun run of `scene` left beside `partial` (a rank killed before rank 0 joined
/// them) into it, creating it (with `provenance`) where there is none: each checked as a partial file of
/// this scene first, each removed once joined (rank_files.hpp).
template <class File, class Scene>
void join_left_rank_files(const std::string& partial, const Scene& scene, const io::Provenance& provenance) {
  const auto ranks = rank_files(partial);
  if (ranks.empty()) return;
  double seconds = 0;
  const auto check = [&](const io::Hdf5Location& f) { File::check_file(f, scene); };
  for (const auto& rank : ranks) check_partial(rank, scene.text, std::nullopt, seconds, check);
  std::optional<File> out;
  if (std::filesystem::exists(partial)) {
    check_partial(partial, scene.text, std::nullopt, seconds, check);
    out.emplace(File::reopen(partial, scene));
  } else {
    out.emplace(partial, scene, provenance);
  }
  for (const auto& rank : ranks) join_rank_file(*out, scene, rank);
  keep_joined(*out);
  out->close();
}

/// Reopens the target's partial file to resume its run (File: io::ResultFile or io::SliderResultFile),
/// after joining the rank files a killed mpirun run left (join_left_rank_files), checked against `scene`
/// and `shard` (check_partial: its wall time so far into earlier_seconds), claims it and adds this
/// binary's instruction set; returns the plan indices of the rows not done and counts the done ones into
/// done_before. Throws, the file untouched, where it is not this run's.
template <class File, class Scene>
std::vector<std::size_t> reopen_partial(std::optional<File>& file, io::OutputTarget& target,
                                        const Scene& scene, const std::optional<io::ShardLabel>& shard,
                                        const io::Provenance& provenance, std::size_t& done_before,
                                        double& earlier_seconds) {
  const std::string partial = target.temporary();
  if (!shard) join_left_rank_files<File>(partial, scene, provenance);
  const auto done = check_partial(partial, scene.text, shard, earlier_seconds,
                                  [&](const io::Hdf5Location& f) { File::check_file(f, scene); });
  file.emplace(File::reopen(partial, scene));
  target.claim_temporary();
  file->add_writer_isa(ensemble::instruction_set().name);
  std::vector<std::size_t> remaining;
  for (std::size_t row = 0; row < done.size(); ++row)
    if (done[row])
      ++done_before;
    else
      remaining.push_back(file->plan_index_of(row));
  return remaining;
}

/// What a sweep streamed into its file left: the sweep's failure (its exception's text), the writer's
/// (the stream's last flush), and the signal that stopped it (0: none).
struct StreamedSweep {
  std::string sweep_error, write_error;
  int signal_number = 0;
};

/// Runs sweep(), which hands its members to `stream`, then flushes `stream`, each failure caught as the
/// commands report it; the members written are then stream.written().
template <class Stream, class Sweep>
StreamedSweep stream_sweep(Stream& stream, const StopOnSignals& signals, Sweep&& sweep) {
  StreamedSweep out;
  try {
    sweep();
  } catch (const std::bad_alloc&) {
    out.sweep_error = "out of memory (an allocation in a worker thread failed)";
  } catch (const std::exception& e) {
    out.sweep_error = e.what();
  }
  out.signal_number = signals.signal();
  try {
    stream.flush();
  } catch (const std::exception& e) {
    out.write_error = e.what();
  }
  return out;
}

/// Says so and returns true when the partial file is no longer the one this run wrote (another process
/// replaced or removed it), so that its `done` members are lost.
bool partial_lost(const io::OutputTarget& target, std::size_t done);

/// The exit code of a run that did not finish, or none where it did: failed (`what` of the run failed:
/// "the sweep", "the scan"; the writer's failure named first, since it stops the sweep), its rows marked
/// done kept for --resume, exit 1; or stopped by SIGINT or SIGTERM, keep_partial() writing its counts and
/// closing the file, exit 128 + the signal. Says what is kept and how to resume (`resume`).
std::optional<int> end_unfinished_run(io::OutputTarget& target, const StreamedSweep& streamed, bool stopped,
                                      const std::string& what, const std::function<void()>& keep_partial,
                                      std::size_t done, std::size_t rows, const std::string& resume);

/// Finishes a run's file (finish(): its last writes, closing it, the outcome's report) and moves it to
/// `path`; where that fails, says so, keeps the partial file (its rows for --resume) and returns false.
bool finish_streamed_run(io::OutputTarget& target, const std::function<void()>& finish,
                         const std::string& path, std::size_t rows, const std::string& resume);

}  // namespace rotorsweep::apps
