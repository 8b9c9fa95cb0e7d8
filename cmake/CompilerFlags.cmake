# Compiler settings shared by every target: C++20, warnings, SIMD target, and no
# floating-point contraction, so that scalar and SIMD lanes round the same way.
set(CMAKE_CXX_STANDARD 20)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
set(CMAKE_CXX_EXTENSIONS OFF)
# The libraries go into the Python module and into other projects' shared libraries as well.
set(CMAKE_POSITION_INDEPENDENT_CODE ON)

add_compile_options(-Wall -Wextra -Wpedantic -ffp-contract=off)
# GCC 12 flags the self-initialised placeholders inside its own AVX-512 intrinsic headers.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  add_compile_options(-Wno-maybe-uninitialized -Wno-uninitialized)
endif()
if(ROTORSWEEP_NATIVE)
  add_compile_options(-march=native)
endif()
