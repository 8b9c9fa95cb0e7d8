// A row sweep on its own thread for the Python module (a BackgroundJob): the plan's members streamed, as
// `rotorsweep run` streams them, into its file on the output path or an in-memory HDF5 image.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "background_job.hpp"
#include "ensemble/rows/member_plan.hpp"
#include "ensemble/rows/scene.hpp"
#include "ensemble/rows/sweep.hpp"
#include "io/output_target.hpp"
#include "io/result_file.hpp"

namespace rotorsweep::python {

/// As `rotorsweep run` and `slider` refuse without --force: throws io::OutputPathError where `target`'s
/// partial file holds the members of an earlier run that stopped early, unless `force`; the partial
/// file is then kept as it is.
void refuse_earlier_partial(io::OutputTarget& target, bool force);

class SweepJob final : public BackgroundJob {
 public:
  /// Starts the scene's whole plan on `threads` threads (0: OpenMP's default). With an output
  /// path the result goes to that file exactly as `rotorsweep run` writes it (checked here,
  /// before the start: io::OutputPathError), through OUTPUT.partial, which keeps the finished members
  /// of a cancelled sweep for `rotorsweep run --resume`; without, it is kept as an in-memory HDF5 image.
  SweepJob(ensemble::Scene scene, int threads, const std::string& output, bool force,
           const io::Provenance& provenance);
  /// Cancels and joins.
  ~SweepJob() override { stop(); }

  /// After wait() returned true: rethrows the sweep's or the writer's error, else returns the
  /// in-memory file's bytes (empty when the result went to the output path).
  std::vector<unsigned char> take_image();

 private:
  void run(int threads);

  ensemble::Scene scene_;
  std::optional<io::OutputTarget> target_;
  std::optional<io::ResultFile> file_;
  std::vector<unsigned char> image_;
};

}  // namespace rotorsweep::python
