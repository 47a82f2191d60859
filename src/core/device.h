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

// For the small functions on every ray's path (normalize, the sampler's next numbers, the
// environment's lookups, the ray offset) that GCC, weighing the integrator's size, would
// otherwise call rather than inline: measured, those calls cost several percent.
#if defined(__CUDACC__)
#define CANDELA_HDI_ALWAYS __host__ __device__ __forceinline__
#else
#define CANDELA_HDI_ALWAYS inline __attribute__((always_inline))
#endif

// For code on a hot path that only some scenes run (the BSDFs other than diffuse): a call keeps
// the integrator small enough that GCC still inlines the helpers every ray runs.
#if defined(__CUDACC__)
#define CANDELA_HD_NOINLINE __host__ __device__ __noinline__
#else
#define CANDELA_HD_NOINLINE __attribute__((noinline))
#endif

// For a query that the GPU's kernel reaches from several places (the BVH traversal): one copy of
// its code there rather than one per call site, each with its own traversal stack. Inlined, the
// kernel's stalls were mostly instruction fetch; out of line it renders the mesh scenes 1.4-1.8x
// as fast on an H200 (docs/performance.md, CUDA backend). The CPU inlines it.
#if defined(__CUDA_ARCH__)
#define CANDELA_HD_GPU_CALL __host__ __device__ __noinline__
#elif defined(__CUDACC__)
#define CANDELA_HD_GPU_CALL __host__ __device__ inline
#else
#define CANDELA_HD_GPU_CALL inline
#endif

// For a query that only some scenes make (the motion BVH's): out of line on the CPU, where GCC
// inlining it slowed the queries every scene makes, and inlined on the GPU, where a call of its
// own would add a traversal stack to every thread's frame.
#if defined(__CUDA_ARCH__)
#define CANDELA_HD_CPU_CALL __host__ __device__ inline
#elif defined(__CUDACC__)
#define CANDELA_HD_CPU_CALL __host__ __device__ __noinline__ inline
#else
#define CANDELA_HD_CPU_CALL inline __attribute__((noinline))
#endif

// For the rare branch of a hot loop (an alpha test in traversal): kept out of line, so that the
// code every ray runs stays small.
#if defined(__CUDACC__)
#define CANDELA_HD_COLD __host__ __device__ __noinline__
#else
#define CANDELA_HD_COLD __attribute__((noinline, cold))
#endif
