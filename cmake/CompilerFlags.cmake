# Compiler settings shared by every target: C++20, warnings, the native SIMD target, and no
# floating-point contraction, so that scalar and SIMD lanes round the same way.
set(CMAKE_CXX_STANDARD 20)
set(CMAKE_CXX_STANDARD_REQUIRED ON)
set(CMAKE_CXX_EXTENSIONS OFF)
# The libraries go into the Python module and into other projects' shared libraries as well.
set(CMAKE_POSITION_INDEPENDENT_CODE ON)

add_compile_options($<$<COMPILE_LANGUAGE:CXX>:-Wall> $<$<COMPILE_LANGUAGE:CXX>:-Wextra>
                    $<$<COMPILE_LANGUAGE:CXX>:-Wpedantic> $<$<COMPILE_LANGUAGE:CXX>:-ffp-contract=off>)
# GCC 12 flags the self-initialised placeholders inside its own AVX-512 intrinsic headers.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
  add_compile_options($<$<COMPILE_LANGUAGE:CXX>:-Wno-maybe-uninitialized> $<$<COMPILE_LANGUAGE:CXX>:-Wno-uninitialized>)
endif()
# A native build compiles everything for this CPU; a portable one the baseline x86-64, except the
# SIMD sweeps and the command line, which get each set's -march (ensemble/, apps/ CMakeLists).
if(NOT ROTORSWEEP_PORTABLE)
  add_compile_options($<$<COMPILE_LANGUAGE:CXX>:-march=native>)
endif()
# Device code: every operation rounded on its own (no fused multiply-add), like the host build, so
# that a GPU thread gives the CPU lanes' bits; constexpr host functions (std::array) callable on it.
set(CMAKE_CUDA_STANDARD 20)
set(CMAKE_CUDA_STANDARD_REQUIRED ON)
set(ROTORSWEEP_CUDA_FLAGS --fmad=false --expt-relaxed-constexpr -Xcompiler=-ffp-contract=off
                          -diag-suppress=186)  # "pointless comparison" in loops over no quadratures
