// A slider scan on its own thread for the Python module (a BackgroundJob): stream_slider_scan with the
// job's stop flag into the file `rotorsweep slider` writes, through its temporary or partial file.
#pragma once

#include <optional>
#include <string>

#include "background_job.hpp"
#include "ensemble/slider/slider_scene.hpp"
#include "io/output_target.hpp"
#include "io/slider_result_file.hpp"

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

}  // namespace rotorsweep::python
