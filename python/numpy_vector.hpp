// Hands a std::vector to NumPy without copying: the array views the vector's buffer and owns the
// vector through a capsule, so the data lives as long as the array does.
#pragma once

#include <pybind11/numpy.h>

#include <utility>
#include <vector>

namespace rotorsweep::python {

/// `values` moved into a NumPy array of `shape` (C order; the product must equal the size).
template <class T>
pybind11::array_t<T> to_numpy(std::vector<T>&& values, std::vector<pybind11::ssize_t> shape) {
  auto* owner = new std::vector<T>(std::move(values));
  const pybind11::capsule free(owner, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return pybind11::array_t<T>(std::move(shape), owner->data(), free);
}

template <class T>
pybind11::array_t<T> to_numpy(std::vector<T>&& values) {
  const auto size = pybind11::ssize_t(values.size());
  return to_numpy(std::move(values), {size});
}

}  // namespace rotorsweep::python
