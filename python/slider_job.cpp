// The Python module's slider thread: every member of the plan through stream_slider_scan, the file
// finished and put in place, or a cancelled scan's finished members kept in the partial file.
#include "slider_job.hpp"

#include <numeric>
#include <stdexcept>
#include <vector>

#include "ensemble/engine/thread_count.hpp"
#include "ensemble/slider/slider_sweep.hpp"
#include "sweep_job.hpp"

namespace rotorsweep::python {

SliderJob::SliderJob(ensemble::SliderScene scene, int threads, const std::string& output, bool force,
                     bool keep, const io::Provenance& provenance)
    : scene_(std::move(scene)), output_(output), keep_(keep) {
  total_ = scene_.member_count();
  const int count = ensemble::thread_count(threads, "threads");
  target_.emplace(output, std::vector<std::string>{provenance.scene_path}, io::Replaceable::hdf5, force,
                  keep);
  if (keep) refuse_earlier_partial(*target_, force);
  file_.emplace(target_->temporary(), scene_, provenance);
  target_->claim_temporary();
  start([this, count] { run(count); });
}

void SliderJob::run(int threads) {
  struct Release {  // the file closed, an unfinished temporary removed (a kept one stays), the locks released
    SliderJob& job;
    ~Release() {
      job.file_.reset();
      job.target_.reset();
    }
  } release{*this};
  std::vector<std::size_t> all(scene_.member_count());
  std::iota(all.begin(), all.end(), std::size_t(0));
  const io::SliderStreamOutcome outcome =
      io::stream_slider_scan(*file_, scene_, all,
                             {threads,
                              [this](std::size_t now) { done_.store(now, std::memory_order_relaxed); },
                              [this] { return cancelled(); },
                              {}});
  if (cancelled()) {
    if (keep_) {  // as `rotorsweep slider` keeps them, for --resume
      file_->keep_partial(outcome.written, outcome.seconds, threads);
      file_->close();
      target_->keep();
      kept_ = outcome.written;
    }
    return;
  }
  if (!outcome.write_error.empty())
    throw std::runtime_error("writing " + output_ + " failed: " + outcome.write_error);
  done_.store(scene_.member_count(), std::memory_order_relaxed);
  file_->finish(outcome.seconds, threads);
  file_->close();
  target_->commit();
}

}  // namespace rotorsweep::python
