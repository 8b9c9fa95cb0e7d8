// The Python module's sweep thread: plan, run_sweep with a stop flag, and the same ResultFile
// writer as `rotorsweep run`, to the output path (through its partial file) or to an in-memory HDF5 image.
#include "sweep_job.hpp"

#include <filesystem>

#include "ensemble/engine/thread_count.hpp"
#include "ensemble/rows/sweep.hpp"

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
    : scene_(std::move(scene)), members_(ensemble::plan_members(scene_)) {
  total_ = members_.size();
  const int count = ensemble::thread_count(threads, "threads");
  if (output.empty()) {
    file_.emplace(io::ResultFile::in_memory(scene_, provenance));
  } else {
    const std::vector<std::string> inputs{provenance.scene_path};
    target_.emplace(output, inputs, io::Replaceable::hdf5, force, true);
    refuse_earlier_partial(*target_, force);  // as `rotorsweep run`: its members are not thrown away
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
  const auto outcome = ensemble::run_sweep(
      scene_, members_, threads, [this](std::size_t done) { done_.store(done, std::memory_order_relaxed); },
      &stop_, &periods_);
  if (!outcome.interrupted) {
    done_.store(members_.size(), std::memory_order_relaxed);
    file_->write_sweep(members_, outcome);
    if (target_) {
      file_->close();
      target_->commit();
    } else {
      image_ = file_->image();
    }
  } else if (target_) {
    keep_finished(outcome);
  }
}

void SweepJob::keep_finished(const ensemble::SweepOutcome& outcome) {
  std::vector<ensemble::MemberResult> finished;
  for (std::size_t i = 0; i < outcome.results.size(); ++i)
    if (outcome.finished[i]) finished.push_back(outcome.results[i]);
  const std::size_t count = finished.size();
  file_->write_results(ensemble::MemberPlan(scene_), std::move(finished));
  file_->keep_partial(count, outcome.statistics);
  file_->close();
  target_->keep();
  kept_ = count;
}

std::vector<unsigned char> SweepJob::take_image() {
  rethrow();
  return std::move(image_);
}

}  // namespace rotorsweep::python
