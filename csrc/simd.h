/*
** simd.h -- which vector instructions the span stages may use, found at
** run time. The shipped core is compiled for the baseline of its target
** (SSE2 on x86-64); on x86-64 with GCC the span chain and the texture
** samplers also have an AVX2 instance (span_stages.h, texsample.c), taken
** when the CPU and the OS support AVX2. Every instance computes the same
** bits, and the baseline stays the portable path that tests compare with.
*/
#ifndef GLES_SIMD_H
#define GLES_SIMD_H

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define SIMD_X86 1   /* GCC's target pragmas and __builtin_cpu_supports */
#else
#define SIMD_X86 0
#endif

enum { SIMD_BASELINE = 0, SIMD_AVX2 = 1 };

/* the instructions of the vector instance, for the code that follows (in
** a push_options / pop_options pair) */
#define SIMD_TARGET_AVX2 _Pragma("GCC target(\"avx2\")")

/* the best instance this CPU can run */
static inline int simd_detect(void)
{
#if SIMD_X86
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") ? SIMD_AVX2 : SIMD_BASELINE;
#else
    return SIMD_BASELINE;
#endif
}

static inline const char *simd_name(int level) { return level == SIMD_AVX2 ? "avx2" : "baseline"; }

#endif
