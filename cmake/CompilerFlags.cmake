# Compiler settings shared by every target: C++20, warnings, position-independent code, and no
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
# Everything is compiled for the baseline x86-64 except the SIMD sweeps, `bench kernels`, the
# tests and the Python module, which get their set's -march (-march=native in a native build;
# ensemble/, apps/, tests/, python/ CMakeLists): code without lanes (Eigen's solvers in the
# landscape) then gives the same bits, free of fused multiply-adds, in native and portable builds.
# Device code: every operation rounded on its own (no fused multiply-add), like the host build, so
# that a GPU thread gives the CPU lanes' bits; constexpr host functions (std::array) callable on it.
set(CMAKE_CUDA_STANDARD 20)
set(CMAKE_CUDA_STANDARD_REQUIRED ON)
# Every nvcc warning is an error (a host function called from device code is only a warning).
set(ROTORSWEEP_CUDA_FLAGS --fmad=false --expt-relaxed-constexpr -Xcompiler=-ffp-contract=off -Werror all-warnings
                          -diag-suppress=186)  # "pointless comparison" in loops over no quadratures
# Code without numerics (scene parsing, files, the command line, the Python bindings) runs for
# milliseconds per run: at -O1 it compiles 30–40 % faster than at -O3, and its files, which spend
# most of their time parsing the same headers, are compiled a few at a time (docs/performance.md,
# build time).
function(rotorsweep_without_numerics target)
  target_compile_options(${target} PRIVATE $<$<AND:$<COMPILE_LANGUAGE:CXX>,$<NOT:$<CONFIG:Debug>>>:-O1>)
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 5)
endfunction()
