/*
** simd.h -- which vector instructions the span stages may use, found at
** run time. The shipped core is compiled for the baseline of its target
** (SSE2 on x86-64); on x86-64 with GCC the span chain and the texture
** samplers also have an AVX2 instance (span_stages.h, texsample.c), taken
** when the CPU and the OS support AVX2 (with BMI1, BMI2 and FMA). The double
** build's bilinear kernel, RGBA8888 writers and fused stage have AVX-512
** (F, DQ, BW) instances besides (span_avx512.h), and so has the fixed
** build's perspective stage with a level of detail (span_fx512.h): eight
** fragments to a register where AVX2 holds four 64-bit lanes. The float
** build's kernels hold eight fragments in AVX2's lanes already and have
** none. Every instance computes the same bits, and the baseline stays the
** portable path that tests compare with.
*/
#ifndef GLES_SIMD_H
#define GLES_SIMD_H

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define SIMD_X86 1   /* GCC's target pragmas and __builtin_cpu_supports */
#else
#define SIMD_X86 0
#endif

enum { SIMD_BASELINE = 0, SIMD_AVX2 = 1, SIMD_AVX512 = 2 };

/* whether this build has an AVX-512 instance: the double build's float
** kernels (SIMD_AVX512_INSTANCE), the fixed build's 64-bit lanes
** (SIMD_AVX512_FX) */
#if SIMD_X86 && defined(GLES_NUM_DOUBLE)
#define SIMD_AVX512_INSTANCE 1
#else
#define SIMD_AVX512_INSTANCE 0
#endif
#if SIMD_X86 && defined(GLES_NUM_FIXED)
#define SIMD_AVX512_FX 1
#else
#define SIMD_AVX512_FX 0
#endif

/* the instructions of the vector instance, for the code that follows (in
** a push_options / pop_options pair). BMI1, BMI2 and FMA come with AVX2 on
** every CPU that has it (Haswell, Excavator, Zen and later); BMI2's shifts
** by a register count take 1-2% off the stages' scalar parts, and the fixed
** build's float-lane kernels (span_avx2.h's modulate-write) fuse their
** products and sums. The core is compiled with -ffp-contract=off, so no
** other a * b + c becomes an FMA: the float builds keep their operations. */
#define SIMD_TARGET_AVX2 _Pragma("GCC target(\"avx2,bmi,bmi2,fma\")")
#define SIMD_TARGET_AVX512 _Pragma("GCC target(\"avx2,bmi,bmi2,fma,avx512f,avx512dq,avx512bw,avx512vl\")")

/* the best instance this CPU can run */
static inline int simd_detect(void)
{
#if SIMD_X86
    __builtin_cpu_init();
    if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("bmi") || !__builtin_cpu_supports("bmi2")
        || !__builtin_cpu_supports("fma"))
        return SIMD_BASELINE;
    /* DQ's 64-bit integer conversions and BW's byte shuffles form the
    ** unorm values (span_avx512.h), and VL's 32 registers hold the fixed
    ** build's fused kernel (span_avx2.h); every AVX-512 CPU but Xeon Phi
    ** has them */
    return (SIMD_AVX512_INSTANCE || SIMD_AVX512_FX) && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq")
                   && __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl")
             ? SIMD_AVX512
             : SIMD_AVX2;
#else
    return SIMD_BASELINE;
#endif
}

static inline const char *simd_name(int level)
{
    return level == SIMD_AVX512 ? "avx512" : (level == SIMD_AVX2 ? "avx2" : "baseline");
}

#endif
