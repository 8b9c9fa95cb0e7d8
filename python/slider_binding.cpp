// Python binding of the slider scan (docs/model.md §9): the scene parsed and checked, the scan on a
// thread of its own while Python keeps Ctrl-C and the progress line, the file `rotorsweep slider` writes.
#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <exception>
#include <numeric>
#include <optional>
#include <thread>

#include "bindings.hpp"
#include "ensemble/engine/instruction_set.hpp"
#include "ensemble/engine/thread_count.hpp"
#include "ensemble/gpu/gpu_slider.hpp"
#include "ensemble/slider/slider_sweep.hpp"
#include "io/output_target.hpp"
#include "io/slider_result_file.hpp"
#include "io/slider_scene_parser.hpp"
#include "sweep_job.hpp"

namespace py = pybind11;

namespace rotorsweep::python {

namespace {

ensemble::SliderScene parse_slider(const std::string& scene, bool is_path) {
  return is_path ? io::parse_slider_scene_file(scene) : io::parse_slider_scene_text(scene, "<scene>");
}

/// Runs the slider scene into `output` (checked before the start: ValueError) and returns its member
/// count; `progress(done, total)` is called about ten times a second, and a signal Python wants to
/// raise (Ctrl-C, or SIGTERM where Python handles it) stops the scan within one step and is raised. The
/// members stream into the temporary file as `rotorsweep slider` streams them: with `keep` into
/// OUTPUT.partial, which then keeps the finished members of a stopped scan (`stopped(kept, total)` is
/// called before the signal is raised), else into a hidden temporary file, which goes.
std::size_t run_slider(const std::string& scene_text, bool is_path, int threads, const std::string& output,
                       bool force, bool keep, const std::string& version, const std::string& revision,
                       const py::object& progress, const py::object& stopped) {
  const auto scene = parse_slider(scene_text, is_path);
  threads = ensemble::thread_count(threads, "threads");
  const std::string source = is_path ? scene_text : std::string("<python>");
  io::OutputTarget target(output, {source}, io::Replaceable::hdf5, force, keep);
  if (keep) refuse_earlier_partial(target, force);
  io::SliderResultFile file(target.temporary(), scene,
                            io::Provenance{source, version, revision, ensemble::slider_device_label(scene),
                                           ensemble::instruction_set().name});
  target.claim_temporary();
  std::atomic<bool> stop{false}, finished{false};
  std::atomic<std::size_t> done{0};
  io::SliderStreamOutcome outcome;
  std::exception_ptr error;
  std::thread worker([&] {
    try {
      std::vector<std::size_t> all(scene.member_count());
      std::iota(all.begin(), all.end(), std::size_t(0));
      outcome = io::stream_slider_scan(
          file, scene, all, {threads, [&](std::size_t now) { done = now; }, [&] { return stop.load(); }, {}});
    } catch (...) {
      error = std::current_exception();
    }
    finished = true;
  });
  bool interrupted = false;
  {
    py::gil_scoped_release release;
    while (!finished) {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      py::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) {
        interrupted = true;
        stop = true;
        break;
      }
      if (!progress.is_none()) progress(done.load(), scene.member_count());
    }
    worker.join();
  }
  if (interrupted) {
    if (keep && !error) {  // as `rotorsweep slider` keeps them, for --resume
      file.keep_partial(outcome.written, outcome.seconds, threads);
      file.close();
      target.keep();
      py::error_scope raised;  // the signal's exception waits while Python is told what was kept
      if (!stopped.is_none()) stopped(outcome.written, scene.member_count());
    }
    throw py::error_already_set();
  }
  if (error) std::rethrow_exception(error);
  if (!outcome.write_error.empty())
    throw std::runtime_error("writing " + output + " failed: " + outcome.write_error);
  if (!progress.is_none()) progress(scene.member_count(), scene.member_count());
  file.finish(outcome.seconds, threads);
  file.close();
  target.commit();
  return scene.member_count();
}

}  // namespace

void bind_slider(py::module_& m) {
  m.def(
      "slider_scene_info",
      [](const std::string& scene, bool is_path) {
        const auto parsed = parse_slider(scene, is_path);
        py::dict info;
        info["output_path"] = parsed.output_path;
        info["members"] = parsed.member_count();
        return info;
      },
      py::arg("scene"), py::arg("is_path") = false,
      "The validated slider scene: its output.path ('' when not given) and member count.");
  m.def("run_slider", &run_slider, py::arg("scene"), py::arg("is_path"), py::arg("threads"),
        py::arg("output"), py::arg("force"), py::arg("keep"), py::arg("version"), py::arg("revision"),
        py::arg("progress") = py::none(), py::arg("stopped") = py::none(),
        "Runs a slider scene (TOML text, or a path with is_path) into the HDF5 file `output`, as "
        "`rotorsweep slider -o output` writes it; returns the member count. Bad scenes and outputs "
        "raise ValueError naming the key; Ctrl-C stops it, keeping the finished members in "
        "output.partial with `keep` (stopped(kept, total) is told), else writing nothing.");
}

}  // namespace rotorsweep::python
