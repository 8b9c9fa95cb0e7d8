// The Python side of a BackgroundJob (python/background_job.hpp) every job class binds the same way:
// wait with the GIL released, done, total, periods, cancel, and what a cancelled job kept.
#pragma once

#include <pybind11/pybind11.h>

namespace rotorsweep::python {

/// Adds the polling members to `job_class` (SweepJob, SliderJob).
template <class Job>
pybind11::class_<Job>& bind_job_polling(pybind11::class_<Job>& job_class) {
  namespace py = pybind11;
  return job_class
      .def("wait", &Job::wait, py::arg("seconds"), py::call_guard<py::gil_scoped_release>(),
           "Waits up to `seconds` (forever when negative) with the GIL released; True once ended.")
      .def_property_readonly("done", &Job::done)
      .def_property_readonly("total", &Job::total)
      .def_property_readonly("periods", &Job::periods,
                             "periods the members have closed so far (0 where the job counts members only)")
      .def("cancel", &Job::cancel)
      .def_property_readonly(
          "kept",
          [](const Job& job) -> py::object {
            const auto kept = job.kept();
            return kept ? py::object(py::int_(*kept)) : py::object(py::none());
          },
          "After a cancelled job with an output path kept: the members kept in OUTPUT.partial (None: no "
          "file kept).");
}

}  // namespace rotorsweep::python
