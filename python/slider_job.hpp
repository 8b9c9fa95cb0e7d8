// A slider scan on its own thread for the Python module (a BackgroundJob): run_slider_members with the
// job's stop flag, through a SliderMemberStream into the file `rotorsweep slider` writes, through its
// temporary or partial file (inline: the binding's unit compiles it, which keeps the module in one unity
// batch).
#pragma once

#include <atomic>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/run_needs.hpp"
#include "background_job.hpp"
#include "ensemble/engine/thread_count.hpp"
#include "ensemble/gpu/gpu_executor.hpp"
#include "ensemble/slider/slider_scene.hpp"
#include "ensemble/slider/slider_sweep.hpp"
#include "io/member_stream.hpp"
#include "io/output_target.hpp"
#include "io/slider_result_file.hpp"
#include "sweep_job.hpp"

namespace rotorsweep::python {

class SliderJob final : public BackgroundJob {
 public:
  /// Starts the scene's whole plan on `threads` threads (0: OpenMP's default) into `output` (checked
  /// here, before the start: io::OutputPathError), as `rotorsweep slider` streams it: with `keep`
  /// through OUTPUT.partial, which keeps the finished members of a cancelled scan (kept()), else
  /// through a hidden temporary file, which goes.
  SliderJob(ensemble::SliderScene scene, int threads, const std::string& output, bool force, bool keep,
            const io::Provenance& provenance);
  /// Cancels and joins.
  ~SliderJob() override { stop(); }

  /// After wait() returned true: rethrows the scan's or the writer's error.
  void finish() { rethrow(); }

 private:
  void run(int threads);

  ensemble::SliderScene scene_;
  std::string output_;
  bool keep_;
  std::optional<io::OutputTarget> target_;
  std::optional<io::SliderResultFile> file_;
};

inline SliderJob::SliderJob(ensemble::SliderScene scene, int threads, const std::string& output, bool force,
                            bool keep, const io::Provenance& provenance)
    : scene_(std::move(scene)), output_(output), keep_(keep) {
  total_ = scene_.member_count();
  const int count = ensemble::thread_count(threads, "threads");
  // as `rotorsweep slider` refuses, before any work: no GPU, too little memory, too little disk
  apps::throw_refusal(apps::gpu_refusal(scene_.device));
  apps::throw_refusal(apps::scan_memory_refusal(scene_, count));
  target_.emplace(output, std::vector<std::string>{provenance.scene_path}, io::Replaceable::hdf5, force,
                  keep);
  if (keep) refuse_earlier_partial(*target_, force);
  apps::throw_refusal(apps::scan_disk_refusal(scene_, total_, false, target_->temporary()));
  file_.emplace(target_->temporary(), scene_, provenance);
  target_->claim_temporary();
  start([this, count] { run(count); });
}

inline void SliderJob::run(int threads) {
  struct Release {  // the file closed, an unfinished temporary removed (a kept one stays), the locks released
    SliderJob& job;
    ~Release() {
      job.file_.reset();
      job.target_.reset();
    }
  } release{*this};
  std::vector<std::size_t> all(scene_.member_count());
  std::iota(all.begin(), all.end(), std::size_t(0));
  std::atomic<bool> write_failed{false};
  io::SliderMemberStream stream(*file_, [&write_failed] { write_failed = true; });
  const auto outcome = ensemble::run_slider_members(
      scene_, all,
      {.threads = threads,
       .progress = [this](std::size_t now) { done_.store(now, std::memory_order_relaxed); },
       .stop = [&] { return cancelled() || write_failed.load(); }},
      [&stream](std::vector<ensemble::SliderMember>&& block) { stream.add(std::move(block)); },
      ensemble::device_for(scene_.device));
  const double seconds = outcome.statistics.wall_seconds;
  const bool finished = end_stream(stream, output_, [&](std::size_t written) {
    if (!keep_) return;  // as `rotorsweep slider` keeps them, for --resume
    file_->keep_partial(written, seconds, threads);
    file_->close();
    target_->keep();
    kept_ = written;
  });
  if (!finished) return;
  file_->finish(seconds, threads);
  file_->close();
  target_->commit();
}

}  // namespace rotorsweep::python
