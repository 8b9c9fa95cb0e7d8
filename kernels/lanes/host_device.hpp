// ROTORSWEEP_HD marks every kernel function for both host and device compilation: it expands to
// __host__ __device__ when nvcc compiles the file and to nothing in the host build. ROTORSWEEP_UNROLL
// asks nvcc to unroll the loop that follows (a register kernel's loops over its slots must be);
// ROTORSWEEP_INLINE makes a function inline wherever it is called (the per-row trigonometry, whose
// values a row model's pass keeps in registers around it).
#pragma once

#if defined(__CUDACC__)
#define ROTORSWEEP_HD __host__ __device__
#define ROTORSWEEP_UNROLL _Pragma("unroll")
#define ROTORSWEEP_INLINE __forceinline__
#else
#define ROTORSWEEP_HD
#define ROTORSWEEP_UNROLL
#define ROTORSWEEP_INLINE [[gnu::always_inline]] inline
#endif
