// The Python module's sweep thread: plan, run_sweep with a stop flag, and the same ResultFile
// writer as `rotorsweep run`, to the output path (through its partial file) or to an in-memory HDF5 image.
#include "sweep_job.hpp"

#include <chrono>
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
  worker_ = std::thread([this, count] { run(count); });
}

SweepJob::~SweepJob() {
  cancel();
  if (worker_.joinable()) worker_.join();
}

void SweepJob::run(int threads) {
  try {
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
  } catch (...) {
    error_ = std::current_exception();
  }
  file_.reset();    // a failed file is closed ...
  target_.reset();  // ... and its temporary removed (a kept one stays), the locks released
  const std::lock_guard guard(lock_);
  finished_ = true;
  ended_.notify_all();
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

bool SweepJob::wait(double seconds) {
  std::unique_lock guard(lock_);
  if (seconds < 0)
    ended_.wait(guard, [this] { return finished_; });
  else
    ended_.wait_for(guard, std::chrono::duration<double>(seconds), [this] { return finished_; });
  return finished_;
}

std::vector<unsigned char> SweepJob::take_image() {
  if (!wait(0)) throw std::logic_error("the sweep is still running");
  if (worker_.joinable()) worker_.join();
  if (error_) std::rethrow_exception(error_);
  return std::move(image_);
}

}  // namespace rotorsweep::python
