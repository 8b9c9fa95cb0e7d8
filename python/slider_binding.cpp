// Python binding of the slider scan (docs/model.md §9): the scene parsed and checked, and SliderJob (the
// scan on a thread of its own; the Python side polls it, draws progress, and cancels on Ctrl-C).
#include <pybind11/pybind11.h>

#include <memory>
#include <string>

#include "bindings.hpp"
#include "ensemble/engine/instruction_set.hpp"
#include "ensemble/gpu/gpu_executor.hpp"
#include "io/slider_scene_parser.hpp"
#include "job_binding.hpp"
#include "slider_job.hpp"

namespace py = pybind11;

namespace rotorsweep::python {

namespace {

ensemble::SliderScene parse_slider(const std::string& scene, bool is_path) {
  return is_path ? io::parse_slider_scene_file(scene) : io::parse_slider_scene_text(scene, "<scene>");
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
  py::class_<SliderJob> slider_job(m, "SliderJob",
                                   "A slider scan on its own thread; poll wait(), read done/total, cancel().");
  bind_job_polling(slider_job)
      .def(py::init([](const std::string& scene, bool is_path, int threads, const std::string& output,
                       bool force, bool keep, const std::string& version, const std::string& revision) {
             const auto parsed = parse_slider(scene, is_path);
             const std::string source = is_path ? scene : std::string("<python>");
             return std::make_unique<SliderJob>(
                 parsed, threads, output, force, keep,
                 io::Provenance{source, version, revision, ensemble::slider_device_label(parsed),
                                ensemble::instruction_set().name});
           }),
           py::arg("scene"), py::arg("is_path"), py::arg("threads"), py::arg("output"), py::arg("force"),
           py::arg("keep"), py::arg("version"), py::arg("revision"),
           "Starts a slider scene (TOML text, or a path with is_path) into the HDF5 file `output`, as "
           "`rotorsweep slider -o output` writes it, through output.partial with `keep` (a cancelled "
           "scan's finished members stay there), else through a hidden temporary file. Bad scenes and "
           "outputs raise ValueError naming the key.")
      .def("finish", &SliderJob::finish, "Raises the scan's error, if any, once it has ended.");
}

}  // namespace rotorsweep::python
