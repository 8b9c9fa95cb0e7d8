// The extension module rotorsweep._core: bad scenes, unusable output paths, thread counts and GPU launch
// settings become ValueError (the command line's exit code 2), everything else RuntimeError.
#include <pybind11/pybind11.h>

#include <string>

#include "bindings.hpp"
#include "build_info.hpp"
#include "ensemble/engine/thread_count.hpp"
#include "ensemble/gpu/gpu_launch.hpp"
#include "io/output_target.hpp"
#include "io/scene_parser.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "rotorsweep's C++ engine (use the rotorsweep package, not this module)";
  m.attr("version") = std::string(rotorsweep::apps::version);
  m.attr("revision") = std::string(rotorsweep::apps::revision);
  pybind11::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const rotorsweep::io::SceneError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const rotorsweep::io::OutputPathError& e) {  // the command line's words, in Python's
      std::string message = e.what();
      for (std::size_t at; (at = message.find("--force")) != std::string::npos;)
        message.replace(at, 7, "force=True");
      PyErr_SetString(PyExc_ValueError, message.c_str());
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
