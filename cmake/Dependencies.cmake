# Finds every external dependency with find_package; nothing is vendored.
# All of them come from Debian packages (scripts/setup.sh installs them).
# Debian's xsimd target names xtl as a link dependency without finding it itself.
find_package(xtl REQUIRED)
find_package(xsimd 8 REQUIRED)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(CLI11 REQUIRED)
find_package(OpenMP REQUIRED COMPONENTS CXX)
find_package(HDF5 REQUIRED COMPONENTS C)
find_package(tomlplusplus 3 REQUIRED)
# FFTW3 (libfftw3-dev) through its pkg-config file: the slider's pair sums and stage products by FFT
find_package(PkgConfig REQUIRED)
pkg_check_modules(FFTW3 REQUIRED IMPORTED_TARGET GLOBAL fftw3)
if(ROTORSWEEP_BUILD_TESTS)
  find_package(Catch2 2 REQUIRED)
endif()

# Distributed sweeps: Open MPI (openmpi-bin, libopenmpi-dev); without it `run` is one process.
if(ROTORSWEEP_MPI)
  find_package(MPI COMPONENTS CXX QUIET)
  if(NOT MPI_CXX_FOUND)
    message(STATUS "MPI not found: rotorsweep run is built without mpirun support")
    set(ROTORSWEEP_MPI OFF)
  endif()
endif()

# The Python module: Debian's interpreter (where python3-numpy, -h5py and -xarray live), pybind11.
if(ROTORSWEEP_PYTHON)
  if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python_EXECUTABLE /usr/bin/python3)
  endif()
  find_package(Python 3.8 COMPONENTS Interpreter Development.Module)
  set(PYBIND11_FINDPYTHON ON)
  if(Python_FOUND)
    find_package(pybind11 2.6 CONFIG QUIET)
  endif()
  if(NOT Python_FOUND OR NOT pybind11_FOUND)
    message(STATUS "Python development files or pybind11 not found: the Python module is left out")
    set(ROTORSWEEP_PYTHON OFF)
  endif()
endif()

# The GPU backend: CUDA's nvcc (Debian's nvidia-cuda-toolkit, or NVIDIA's in /usr/local/cuda). No GPU is
# needed to build or test it; without nvcc the backend is left out and numerics.device = "gpu" says so.
if(ROTORSWEEP_CUDA)
  if(NOT DEFINED CMAKE_CUDA_COMPILER AND NOT DEFINED ENV{CUDACXX} AND EXISTS /usr/local/cuda/bin/nvcc)
    set(CMAKE_CUDA_COMPILER /usr/local/cuda/bin/nvcc)
  endif()
  include(CheckLanguage)
  check_language(CUDA)
  if(CMAKE_CUDA_COMPILER)
    if(NOT DEFINED CMAKE_CUDA_ARCHITECTURES)
      # PTX for one virtual architecture: cheap to compile, JIT-compiled by the driver at first run.
      # The gpu preset adds sm_90 machine code (H100, H200); e.g. -DCMAKE_CUDA_ARCHITECTURES=80 for an A100.
      set(CMAKE_CUDA_ARCHITECTURES 90-virtual)
    endif()
    enable_language(CUDA)
    # CMake before 3.26 knows nvcc's dialects up to C++17 only; nvcc 12 and later take C++20
    if(NOT CMAKE_CUDA20_STANDARD_COMPILE_OPTION)
      set(CMAKE_CUDA20_STANDARD_COMPILE_OPTION "-std=c++20")
      set(CMAKE_CUDA20_EXTENSION_COMPILE_OPTION "-std=c++20")
    endif()
    find_package(CUDAToolkit REQUIRED)
  else()
    message(STATUS "nvcc not found: rotorsweep is built without the GPU backend")
    set(ROTORSWEEP_CUDA OFF)
  endif()
endif()
