# Every build option of rotorsweep, declared in one place.
# Defaults give an optimised, portable build with tests (instruction sets: cmake/InstructionSets.cmake).
option(ROTORSWEEP_BUILD_TESTS "Build the Catch2 test suite" ON)
option(ROTORSWEEP_BUILD_BENCH "Build the peer benchmarks in bench/ (needs libsundials-dev)" OFF)
option(ROTORSWEEP_PYTHON "Build the Python module (needs pybind11-dev and python3-dev; off when absent)" ON)

if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE Release CACHE STRING "Build type" FORCE)
endif()
option(ROTORSWEEP_MPI "Let rotorsweep run share a plan between mpirun ranks (needs libopenmpi-dev; off when absent)" ON)
option(ROTORSWEEP_CUDA "Build the GPU backend (numerics.device = \"gpu\"; needs nvcc, off when absent)" ON)
# The register kernels' shapes (docs/architecture.md "Register kernels"): lanes x slots per lane, "d"
# for disordered rows, "q" for every quadrature (W, S, H and the moments beside R and ρ̄; without it a
# scene asking for them runs on teams or a thread per member), "sS" for S stage vectors (tableaus of at
# most S stages; 8 without it), "bB" for B blocks of 128 threads resident per multiprocessor (registers
# capped, the rest spilled; none without it); each is a CUDA unit of its own. The default holds N = 8 … 24 (the suite's and the
# examples'): six stage vectors at 3 blocks for rodas4 and rodas4p2 (the fastest measured,
# docs/performance.md), eight for rodas5p, disordered rows; the gpu preset compiles every shape it measures.
set(ROTORSWEEP_GPU_REGISTER_SHAPES "8x3s6b3;8x3;8x3d" CACHE STRING "Register kernel shapes LxR[d][q][sS][bB] for the GPU backend")
# Shapes among them whose machine code must not spill (ptxas --warn-on-spills, an error): the gpu
# preset lists those ptxas compiles without spills (docs/performance.md "Rows in registers: what
# ptxas says"); a build of PTX alone runs no ptxas and checks nothing.
set(ROTORSWEEP_GPU_SPILL_FREE_SHAPES "" CACHE STRING "Register kernel shapes whose machine code must not spill")
# test_gpu, the GPU backend's checks on a device (ctest gpu_backend): built by the gpu preset, which
# is what a device runs; elsewhere it could only be skipped.
option(ROTORSWEEP_DEVICE_TESTS "Build test_gpu, the GPU backend's tests on a device" OFF)
