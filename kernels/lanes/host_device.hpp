// ROTORSWEEP_HD marks every kernel function for both host and device compilation: it expands to
// __host__ __device__ when nvcc compiles the file and to nothing in the host build.
#pragma once

#if defined(__CUDACC__)
#define ROTORSWEEP_HD __host__ __device__
#else
#define ROTORSWEEP_HD
#endif
