// The one macro that marks code shared by the CPU and the CUDA backends.
//
// Every function the integrator can reach is CANDELA_HD: the same source is compiled by the host
// compiler and by nvcc. Such code uses no STL containers, strings, exceptions or virtual calls.
#pragma once

#if defined(__CUDACC__)
#define CANDELA_HD __host__ __device__
#define CANDELA_DEVICE_CODE 1
#else
#define CANDELA_HD
#define CANDELA_DEVICE_CODE 0
#endif

#define CANDELA_HDI CANDELA_HD inline
