// The extension module rotorsweep._core: bad scenes, unusable output paths, thread counts, GPU launch
// settings and runs refused for memory, disk or a GPU become ValueError (the command line's exit code 2),
// everything else RuntimeError.
#include <pybind11/pybind11.h>

#include <string>
#include <utility>

#include "apps/run_needs.hpp"
#include "bindings.hpp"
#include "build_info.hpp"
#include "ensemble/engine/thread_count.hpp"
#include "ensemble/gpu/gpu_launch.hpp"
#include "io/output_target.hpp"
#include "io/scene_parser.hpp"

namespace {

/// The command line's words in Python's: its options as the functions' arguments.
std::string python_words(std::string message) {
  for (const auto& [cli, python] : {std::pair<std::string, std::string>{"--force", "force=True"},
                                    {" (or --device gpu)", ""},
                                    {"run with --device cpu", "set numerics.device = \"cpu\""},
                                    {"--threads", "threads"},
                                    {"--A-cells", "A_cells"},
                                    {"--tau-cells", "tau_cells"},
                                    {"--samples", "count"}})
    for (std::size_t at; (at = message.find(cli)) != std::string::npos;) message.replace(at, cli.size(), python);
  return message;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "rotorsweep's C++ engine (use the rotorsweep package, not this module)";
  m.attr("version") = std::string(rotorsweep::apps::version);
  m.attr("revision") = std::string(rotorsweep::apps::revision);
  pybind11::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const rotorsweep::io::SceneError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const rotorsweep::io::OutputPathError& e) {
      PyErr_SetString(PyExc_ValueError, python_words(e.what()).c_str());
    } catch (const rotorsweep::apps::RunRefused& e) {  // too little memory or disk, no GPU
      PyErr_SetString(PyExc_ValueError, python_words(e.what()).c_str());
    } catch (const rotorsweep::ensemble::ThreadCountError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const rotorsweep::ensemble::GpuLaunchError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  rotorsweep::python::bind_sweep(m);
  rotorsweep::python::bind_landscape(m);
  rotorsweep::python::bind_slider(m);
}
