// The parts of the rotorsweep._core extension module, one binding function per source file.
#pragma once

#include <pybind11/pybind11.h>

namespace rotorsweep::python {

void bind_sweep(pybind11::module_& m);      ///< sweep_binding.cpp
void bind_landscape(pybind11::module_& m);  ///< landscape_binding.cpp
void bind_slider(pybind11::module_& m);     ///< slider_binding.cpp

}  // namespace rotorsweep::python
