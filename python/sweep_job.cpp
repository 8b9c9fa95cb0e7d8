// The Python module's sweep thread: the plan's members streamed into the same ResultFile `rotorsweep run`
// writes, on the output path (through its partial file) or in an in-memory HDF5 image.
#include "sweep_job.hpp"

#include <atomic>
#include <filesystem>

#include "apps/run_needs.hpp"
#include "ensemble/engine/thread_count.hpp"
#include "ensemble/gpu/gpu_executor.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/member_stream.hpp"

namespace rotorsweep::python {

void refuse_earlier_partial(io::OutputTarget& target, bool force) {
  if (force || !std::filesystem::exists(target.temporary())) return;
  target.keep();  // it stays as it is
  throw io::OutputPathError(target.temporary() +
                            " holds the finished members of an earlier run that stopped early: continue it "
                            "with `rotorsweep run` or `rotorsweep slider` and --resume, or start afresh with "
                            "force=True");
}

SweepJob::SweepJob(ensemble::Scene scene, int threads, const std::string& output, bool force,
                   const io::Provenance& provenance)
    : scene_(std::move(scene)) {
  total_ = ensemble::MemberPlan(scene_).size();
  const int count = ensemble::thread_count(threads, "threads");
  // as `rotorsweep run` refuses, before any work: no GPU, too little memory (a result kept in memory
  // counted too), too little disk
  apps::throw_refusal(apps::gpu_refusal(scene_.device));
  apps::throw_refusal(apps::sweep_memory_refusal(
      scene_, count, output.empty() ? apps::sweep_disk_bytes(scene_, total_, false) : 0.0));
  if (output.empty()) {
    file_.emplace(io::ResultFile::in_memory(scene_, provenance));
  } else {
    const std::vector<std::string> inputs{provenance.scene_path};
    target_.emplace(output, inputs, io::Replaceable::hdf5, force, true);
    refuse_earlier_partial(*target_, force);  // as `rotorsweep run`: its members are not thrown away
    apps::throw_refusal(apps::sweep_disk_refusal(scene_, total_, false, target_->temporary()));
    file_.emplace(target_->temporary(), scene_, provenance);
    target_->claim_temporary();
  }
  start([this, count] { run(count); });
}

void SweepJob::run(int threads) {
  struct Release {  // a failed file is closed and its temporary removed (a kept one stays), the locks
                    // released
    SweepJob& job;
    ~Release() {
      job.file_.reset();
      job.target_.reset();
    }
  } release{*this};
  const ensemble::MemberPlan plan(scene_);
  const ensemble::MemberSource source{plan.size(), [&plan](std::size_t k) { return plan[k]; }};
  std::atomic<bool> write_failed{false};
  io::MemberStream stream(*file_, plan, {}, [&write_failed] { write_failed = true; });
  const auto outcome = ensemble::run_members(
      scene_, source,
      {.threads = threads,
       .progress = [this](std::size_t done) { done_.store(done, std::memory_order_relaxed); },
       .stop = [&] { return cancelled() || write_failed.load(); },
       .stops = &periods_},
      [&stream](ensemble::MemberResult&& result) { stream.add(std::move(result)); },
      ensemble::device_for(scene_.device));
  const bool finished =
      end_stream(stream, target_ ? target_->temporary() : "the result", [&](std::size_t written) {
        if (!target_) return;  // as `rotorsweep run` keeps them, for --resume
        file_->keep_partial(written, outcome.statistics);
        file_->close();
        target_->keep();
        kept_ = written;
      });
  if (!finished) return;
  file_->finish(outcome.statistics);
  if (target_) {
    file_->close();
    target_->commit();
  } else {
    image_ = file_->image();
  }
}

std::vector<unsigned char> SweepJob::take_image() {
  rethrow();
  return std::move(image_);
}

}  // namespace rotorsweep::python
