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
if(ROTORSWEEP_BUILD_TESTS)
  find_package(Catch2 2 REQUIRED)
endif()
