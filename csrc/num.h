/*
** num.h -- the numeric layer: one switchboard for the three builds.
** Owns: the NUM type and every arithmetic operation the pipeline uses on it,
**       plus the few wider types the rasterizer needs (weights, depth values).
** Build: exactly one of GLES_NUM_FIXED, GLES_NUM_FLOAT, GLES_NUM_DOUBLE is
**        defined by the compiler command line. No other file tests which.
**
** Fixed build (the product). NUM is s15.16 in an int32_t. Every product and
** quotient uses a 64-bit intermediate, rounds to nearest (ties away from
** zero) and saturates to [NUM_MIN, NUM_MAX]: overflow never wraps. Negative
** values are never shifted left (undefined in C11); we multiply instead.
**
** Float and double builds. NUM is the IEEE type; operations are the plain
** operators. Conversions to integers (window coordinates, colour and depth
** values) go through num_to_i64 / *_sat helpers that map NaN to 0 and clamp
** infinities, because a float-to-int conversion out of range is undefined.
**
** Rasterizer weights. Barycentric weights are WGT: in the fixed build an
** int32 in 0.30 (1.0 = 2^30), elsewhere NUM. Depth values per vertex are
** DEPTHV: depth-buffer units with 16 fraction bits in an int64 (fixed), or
** NUM. Both are evaluated with the helpers at the end of this file.
*/
#ifndef GLES_NUM_H
#define GLES_NUM_H

#include <stdint.h>
#include <math.h>

#if defined(GLES_NUM_FIXED) + defined(GLES_NUM_FLOAT) + defined(GLES_NUM_DOUBLE) != 1
#error "define exactly one of GLES_NUM_FIXED, GLES_NUM_FLOAT, GLES_NUM_DOUBLE"
#endif

/* {==================================================================== */
/* Integer helpers shared by every build */

static inline int64_t i64_clamp(int64_t v, int64_t lo, int64_t hi)
{
    return v < lo ? lo : (v > hi ? hi : v);
}

/* floor(n / d) and ceil(n / d) for d > 0 */
static inline int64_t i64_floor_div(int64_t n, int64_t d)
{
    int64_t q = n / d;
    return (n % d != 0 && n < 0) ? q - 1 : q;
}

static inline int64_t i64_ceil_div(int64_t n, int64_t d)
{
    int64_t q = n / d;
    return (n % d != 0 && n > 0) ? q + 1 : q;
}

/* n / d rounded to nearest, ties away from zero; d != 0 */
static inline int64_t i64_round_div(int64_t n, int64_t d)
{
    uint64_t an = n < 0 ? (uint64_t)0 - (uint64_t)n : (uint64_t)n;
    uint64_t ad = d < 0 ? (uint64_t)0 - (uint64_t)d : (uint64_t)d;
    uint64_t q = (an + ad / 2) / ad;
    if (an > UINT64_MAX - ad / 2) /* cannot happen for our ranges; stay defined */
        q = an / ad;
    if (q > (uint64_t)INT64_MAX)
        q = (uint64_t)INT64_MAX;
    return ((n < 0) != (d < 0)) ? -(int64_t)q : (int64_t)q;
}

/* n / 2^k truncated toward zero, as C's n / ((int64_t)1 << k), without a
** division instruction (0 <= k <= 62) */
static inline int64_t i64_div_pow2(int64_t n, int k)
{
    int64_t bias = n < 0 ? (((int64_t)1 << k) - 1) : 0;
    return (n + bias) >> k;
}

/* number of significant bits of a non-negative value (0 for 0) */
static inline int u64_bits(uint64_t v)
{
    return v ? 64 - __builtin_clzll(v) : 0;
}

/* Double to int64, NaN to 0, clamped to [lo, hi], rounded to nearest. */
static inline int64_t dbl_to_i64(double v, int64_t lo, int64_t hi)
{
    if (!(v == v))
        return 0;
    if (v <= (double)lo)
        return lo;
    if (v >= (double)hi)
        return hi;
    return (int64_t)floor(v + 0.5);
}

/* }==================================================================== */

#if defined(GLES_NUM_FIXED)
/* {==================================================================== */
/* Fixed build: s15.16 */

typedef int32_t NUM;
#define NUM_NAME "fixed"
#define NUM_IS_FIXED 1
#define NUM_ONE ((NUM)65536)
#define NUM_HALF ((NUM)32768)
#define NUM_ZERO ((NUM)0)
#define NUM_MAX ((NUM)INT32_MAX)
#define NUM_MIN ((NUM)INT32_MIN)
#define NUM_EPS ((NUM)1) /* the smallest positive value, 2^-16 */
#define NUM_FRAC_BITS 16

static inline NUM num_sat(int64_t v)
{
    return (NUM)i64_clamp(v, INT32_MIN, INT32_MAX);
}

/* round a value with `bits` fraction bits to 16.16 */
static inline NUM num_from_scaled(int64_t v, int bits)
{
    if (bits <= 16)
        return num_sat(v * ((int64_t)1 << (16 - bits)));
    int s = bits - 16;
    int64_t half = (int64_t)1 << (s - 1);
    /* ties away from zero, symmetric for negative values */
    int64_t r = v >= 0 ? (v + half) >> s : -((-v + half) >> s);
    return num_sat(r);
}

static inline NUM num_from_int(int64_t i) { return num_sat(i * 65536); }
static inline NUM num_from_fixed(int32_t x) { return x; }
static inline NUM num_from_double(double d) { return (NUM)dbl_to_i64(d * 65536.0, INT32_MIN, INT32_MAX); }
static inline double num_to_double(NUM a) { return a / 65536.0; }
static inline int32_t num_to_fixed(NUM a) { return a; }

static inline NUM num_add(NUM a, NUM b) { return num_sat((int64_t)a + b); }
static inline NUM num_sub(NUM a, NUM b) { return num_sat((int64_t)a - b); }
static inline NUM num_neg(NUM a) { return num_sat(-(int64_t)a); }
static inline NUM num_abs(NUM a) { return num_sat(a < 0 ? -(int64_t)a : a); }

static inline NUM num_mul(NUM a, NUM b)
{
    return num_from_scaled((int64_t)a * b, 32);
}

static inline NUM num_div(NUM a, NUM b)
{
    if (b == 0)
        return a > 0 ? NUM_MAX : (a < 0 ? NUM_MIN : 0);
    return num_sat(i64_round_div((int64_t)a * 65536, b));
}

static inline NUM num_recip(NUM a) { return num_div(NUM_ONE, a); }

/* NUMW: the exact sum or difference of two NUMs (r - l with r = -l = 20000
** does not fit 16.16, but its ratio to another may); a ratio of two is
** rounded once into NUM */
typedef int64_t NUMW;
static inline NUMW numw(NUM a) { return a; }
static inline NUM num_div_w(NUMW a, NUMW b)
{
    if (b == 0)
        return a > 0 ? NUM_MAX : (a < 0 ? NUM_MIN : 0);
    if (b < 0) {
        a = -a;
        b = -b;
    }
    return num_sat(i64_round_div(a * 65536, b)); /* |a| < 2^33: no overflow */
}
/* k*a*b / c with the product exact in 64 bits (|k| <= 2), rounded once */
static inline NUM num_muldiv_w(int k, NUM a, NUM b, NUMW c)
{
    int64_t p = (int64_t)a * b;   /* |p| <= 2^62 */
    if (p > INT64_MAX / 2 || p < -(INT64_MAX / 2))
        p = p > 0 ? INT64_MAX / 2 : -(INT64_MAX / 2);
    p *= k;
    if (c == 0)
        return p > 0 ? NUM_MAX : (p < 0 ? NUM_MIN : 0);
    if (c < 0) {
        p = -p;
        c = -c;
    }
    return num_sat(i64_round_div(p, c));
}

/* floor(sqrt(v)) for v >= 0, exact */
static inline uint64_t u64_isqrt(uint64_t v)
{
    uint64_t r = (uint64_t)sqrt((double)v); /* close; then correct exactly */
    while (r > 0 && r * r > v)
        r--;
    while ((r + 1) * (r + 1) <= v)
        r++;
    return r;
}

/* sqrt rounded to nearest: the 16.16 result is sqrt(a * 2^16) for raw a */
static inline NUM num_sqrt(NUM a)
{
    if (a <= 0)
        return 0;
    uint64_t v = (uint64_t)a << 16;   /* a / 2^16 * 2^32 */
    uint64_t r = u64_isqrt(v);
    /* round: r + 1 if (r + 0.5)^2 <= v, i.e. r^2 + r < v */
    if (r * r + r < v)
        r++;
    return num_sat((int64_t)r);
}

/* 1 / sqrt(a): via a 0.62 numerator so small inputs keep their precision */
static inline NUM num_rsqrt(NUM a)
{
    if (a <= 0)
        return NUM_MAX;
    /* 1/sqrt(a/2^16) * 2^16 = 2^24 / sqrt(a) = sqrt(2^48 / a) */
    uint64_t q = ((uint64_t)1 << 62) / (uint64_t)a;   /* 2^62/a */
    uint64_t r = u64_isqrt(q);                        /* 2^31/sqrt(a) */
    return num_sat((int64_t)((r + 64) >> 7));         /* 2^24/sqrt(a) */
}

#define NUM_LIT(d) ((NUM)((d) * 65536.0 + ((d) >= 0 ? 0.5 : -0.5)))

/* }==================================================================== */
#else
/* {==================================================================== */
/* Float and double builds */

#if defined(GLES_NUM_FLOAT)
typedef float NUM;
#define NUM_NAME "float"
#define NUM_MAX ((NUM)3.402823466e38f)
#define NUM_SQRT sqrtf
#define NUM_POW powf
#define NUM_FLOOR floorf
#else
typedef double NUM;
#define NUM_NAME "double"
#define NUM_MAX ((NUM)1.7976931348623157e308)
#define NUM_SQRT sqrt
#define NUM_POW pow
#define NUM_FLOOR floor
#endif
#define NUM_IS_FIXED 0
#define NUM_ONE ((NUM)1)
#define NUM_HALF ((NUM)0.5)
#define NUM_ZERO ((NUM)0)
#define NUM_MIN (-NUM_MAX)
#define NUM_EPS ((NUM)(1.0 / 65536.0)) /* same guard values as the fixed build */
#define NUM_LIT(d) ((NUM)(d))

static inline NUM num_from_int(int64_t i) { return (NUM)i; }
static inline NUM num_from_fixed(int32_t x) { return (NUM)(x / 65536.0); }
static inline NUM num_from_double(double d) { return (NUM)d; }
static inline NUM num_from_scaled(int64_t v, int bits) { return (NUM)ldexp((double)v, -bits); }
static inline double num_to_double(NUM a) { return (double)a; }
static inline int32_t num_to_fixed(NUM a) { return (int32_t)dbl_to_i64((double)a * 65536.0, INT32_MIN, INT32_MAX); }

static inline NUM num_add(NUM a, NUM b) { return a + b; }
static inline NUM num_sub(NUM a, NUM b) { return a - b; }
static inline NUM num_neg(NUM a) { return -a; }
static inline NUM num_abs(NUM a) { return a < 0 ? -a : a; }
static inline NUM num_mul(NUM a, NUM b) { return a * b; }
static inline NUM num_div(NUM a, NUM b) { return a / b; }
static inline NUM num_recip(NUM a) { return NUM_ONE / a; }
typedef NUM NUMW;
static inline NUMW numw(NUM a) { return a; }
static inline NUM num_div_w(NUMW a, NUMW b) { return a / b; }
static inline NUM num_muldiv_w(int k, NUM a, NUM b, NUMW c) { return (NUM)k * a * b / c; }
static inline NUM num_sqrt(NUM a) { return a > 0 ? NUM_SQRT(a) : 0; }
static inline NUM num_rsqrt(NUM a) { return a > 0 ? NUM_ONE / NUM_SQRT(a) : NUM_MAX; }

/* }==================================================================== */
#endif

static inline NUM num_min(NUM a, NUM b) { return a < b ? a : b; }
static inline NUM num_max(NUM a, NUM b) { return a > b ? a : b; }
static inline NUM num_clamp01(NUM a) { return a < NUM_ZERO ? NUM_ZERO : (a > NUM_ONE ? NUM_ONE : a); }
static inline NUM num_clamp_range(NUM a, NUM lo, NUM hi) { return a < lo ? lo : (a > hi ? hi : a); }

/* a * b where b is an integer (counts, sizes): exact in every build */
static inline NUM num_mul_int(NUM a, int64_t b)
{
#if NUM_IS_FIXED
    return num_sat((int64_t)a * b);
#else
    return a * (NUM)b;
#endif
}

/* value in [0,1] to an integer in [0, maxval], rounded to nearest */
static inline uint32_t num_to_unorm(NUM a, uint32_t maxval)
{
#if NUM_IS_FIXED
    if (a <= 0)
        return 0;
    if (a >= NUM_ONE)
        return maxval;
    return (uint32_t)(((int64_t)a * maxval + 32768) >> 16);
#else
    if (!(a > 0))
        return 0; /* also NaN */
    if (a >= NUM_ONE)
        return maxval;
    return (uint32_t)((double)a * maxval + 0.5);
#endif
}

/* c / maxval, the spec's unsigned normalised conversion (Table 2.7) */
static inline NUM num_from_unorm(uint32_t c, uint32_t maxval)
{
#if NUM_IS_FIXED
    return (NUM)i64_round_div((int64_t)c * 65536, maxval);
#else
    return (NUM)((double)c / maxval);
#endif
}

/* (2c + 1) / (2^bits - 1), the spec's signed normalised conversion */
static inline NUM num_from_snorm(int32_t c, uint32_t maxval)
{
#if NUM_IS_FIXED
    return (NUM)i64_round_div(((int64_t)c * 2 + 1) * 65536, maxval);
#else
    return (NUM)(((double)c * 2 + 1) / maxval);
#endif
}

/* {==================================================================== */
/* Dot products with one rounding (matrix and vector work) */

#if NUM_IS_FIXED
/* An exact sum of up to 16 products of two NUMs (32 fraction bits). One
** product fits 63 bits but four need 65, so the sum is kept wider: in
** __int128 where the compiler has it, else as the parts above and below
** 2^16 added apart. num_acc_round gives the sum as 16.16, rounded once
** (ties away from zero, as num_from_scaled) and saturated. */
#if defined(__SIZEOF_INT128__)
__extension__ typedef __int128 NumAcc;
#define NUM_ACC_ADD(acc, p) ((acc) += (p))
static inline NUM num_acc_round(NumAcc acc)
{
    const int64_t alim = INT64_MAX - ((int64_t)1 << 31);
    if (acc >= alim)
        return NUM_MAX;
    if (acc <= -alim)
        return NUM_MIN;
    return num_from_scaled((int64_t)acc, 32);
}
#else
typedef struct NumAcc { int64_t hi, lo; } NumAcc;
#define NUM_ACC_ADD(acc, p) ((acc).hi += (p) / 65536, (acc).lo += (p) % 65536)
static inline NUM num_acc_round(NumAcc acc)
{
    int64_t t = acc.hi + acc.lo / 65536, l = acc.lo % 65536;
    const int64_t tlim = ((int64_t)1 << 47) - 2, alim = INT64_MAX - ((int64_t)1 << 31);
    if (t > tlim)
        return NUM_MAX;
    if (t < -tlim)
        return NUM_MIN;
    int64_t v = t * 65536 + l;
    if (v >= alim)
        return NUM_MAX;
    if (v <= -alim)
        return NUM_MIN;
    return num_from_scaled(v, 32);
}
#endif
#endif

/* sum of a[i*as] * b[i*bs] for i < n, rounded once */
static inline NUM num_dot(const NUM *a, int as, const NUM *b, int bs, int n)
{
#if NUM_IS_FIXED
    NumAcc acc = { 0 };
    for (int i = 0; i < n; i++) {
        int64_t p = (int64_t)a[i * as] * b[i * bs];
        NUM_ACC_ADD(acc, p);
    }
    return num_acc_round(acc);
#else
    NUM acc = 0;
    for (int i = 0; i < n; i++)
        acc += a[i * as] * b[i * bs];
    return acc;
#endif
}

/* Normalise v in place. The fixed build first divides by the largest
** component so the sum of squares stays in range whatever the length.
** Returns 0 (v unchanged) for a zero vector. */
static inline int num_normalize3(NUM *v)
{
    NUM m = num_max(num_abs(v[0]), num_max(num_abs(v[1]), num_abs(v[2])));
    if (m == NUM_ZERO)
        return 0;
#if NUM_IS_FIXED
    /* scale by a power of two so the largest component is in [1/2, 1):
    ** exact for small vectors, keeps 15 significant bits of large ones */
    int sh = u64_bits((uint64_t)(uint32_t)m) - 16;
    int64_t w[3];
    for (int i = 0; i < 3; i++)
        w[i] = sh >= 0 ? (int64_t)v[i] / ((int64_t)1 << sh) : (int64_t)v[i] * ((int64_t)1 << -sh);
    int64_t ss = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];   /* 32 fraction bits, in [1/4, 3) */
    NUM inv = num_rsqrt(num_from_scaled(ss, 32));
    for (int i = 0; i < 3; i++)
        v[i] = num_from_scaled(w[i] * inv, 32);
#else
    NUM inv = num_rsqrt(num_dot(v, 1, v, 1, 3));
    for (int i = 0; i < 3; i++)
        v[i] = num_mul(v[i], inv);
#endif
    return 1;
}
/* }==================================================================== */

/* {==================================================================== */
/* Sine and cosine of an angle in degrees (glRotate) */

#if NUM_IS_FIXED
/* sin(pi/2 * t) for t in [0,1] in 0.30: the degree-11 Taylor polynomial in
** 64-bit integers; truncation error below 2^-24, far under the 2^-17 that
** the final rounding to 16.16 adds. */
static inline int64_t fx_sin_quarter(int64_t t30)
{
    /* coefficients of sin(pi/2 t) = sum c_k t^(2k+1), in 0.30 */
    static const int64_t c[6] = {
        1686629713LL,   /*  pi/2          */
        -693598668LL,   /* -(pi/2)^3/3!   */
        85569306LL,     /*  (pi/2)^5/5!   */
        -5026995LL,     /* -(pi/2)^7/7!   */
        172272LL,       /*  (pi/2)^9/9!   */
        -3864LL,        /* -(pi/2)^11/11! */
    };
    int64_t t2 = (t30 * t30) >> 30;
    int64_t acc = c[5];
    for (int k = 4; k >= 0; k--)
        acc = c[k] + ((acc * t2) >> 30);
    return (acc * t30) >> 30;
}

/* sin and cos of `deg` degrees (16.16) */
static inline void num_sincos_deg(NUM deg, NUM *s, NUM *co)
{
    /* reduce exactly: 360 degrees = 360 * 65536 units */
    int64_t full = (int64_t)360 * 65536;
    int64_t a = deg % full;
    if (a < 0)
        a += full;
    int64_t quarter = (int64_t)90 * 65536;
    int q = (int)(a / quarter);
    int64_t r = a - (int64_t)q * quarter;          /* [0, 90) degrees */
    int64_t t = (r * ((int64_t)1 << 30)) / quarter; /* 0.30 fraction of a quarter */
    int64_t sn = fx_sin_quarter(t);
    int64_t cs = fx_sin_quarter(((int64_t)1 << 30) - t);
    int64_t sv, cv;
    switch (q) {
    case 0: sv = sn; cv = cs; break;
    case 1: sv = cs; cv = -sn; break;
    case 2: sv = -sn; cv = -cs; break;
    default: sv = -cs; cv = sn; break;
    }
    *s = num_from_scaled(sv, 30);
    *co = num_from_scaled(cv, 30);
}
#else
static inline void num_sincos_deg(NUM deg, NUM *s, NUM *co)
{
    /* reduce in degrees first so that multiples of 90 are exact */
    double a = fmod((double)deg, 360.0);
    if (a < 0)
        a += 360.0;
    const double pi = 3.14159265358979323846;
    if (a == 0.0) { *s = 0; *co = 1; return; }
    if (a == 90.0) { *s = 1; *co = 0; return; }
    if (a == 180.0) { *s = 0; *co = -1; return; }
    if (a == 270.0) { *s = -1; *co = 0; return; }
    *s = (NUM)sin(a * pi / 180.0);
    *co = (NUM)cos(a * pi / 180.0);
}
#endif
/* }==================================================================== */

/* {==================================================================== */
/* Powers for lighting: x^s with x >= 0, s in [0,128] (specular and spot
** exponents). The fixed build computes exp2(s * log2(x)) in 64-bit integers
** with 30 fraction bits: table plus a short series for each, so the
** error stays near 2^-16 whatever the exponent (a table lookup alone would
** grow with s). 0^0 is 1. */

#if NUM_IS_FIXED
#include "tables.h"

/* log2(x) for raw x > 0, in 0.30: the table at the top 8 fraction bits of
** the mantissa, then log2(1 + y) = (y - y^2/2 + y^3/3) / ln 2 for the rest
** (y < 2^-8, so the first omitted term is below 2^-34) */
static inline int64_t fx_log2(int32_t x)
{
    const int64_t one = (int64_t)1 << 30, inv_ln2 = 1549082005LL; /* 1/ln 2 in 2.30 */
    int b = u64_bits((uint64_t)x);
    int64_t m = (int64_t)((uint64_t)x << (31 - b));     /* [2^30, 2^31): 1.30 */
    int64_t frac = m - one;
    int i = (int)(frac >> 22);
    int64_t y = ((frac & ((1 << 22) - 1)) * fx_recip_tab[i]) >> 30;   /* r / (1 + i/256) */
    int64_t y2 = (y * y) >> 30, y3 = (y2 * y) >> 30;
    int64_t ln1p = y - y2 / 2 + y3 / 3;
    return (int64_t)(b - 17) * one + fx_log2_tab[i] + ((ln1p * inv_ln2) >> 30);
}

/* 2^y for y in 0.30, as 16.16 (saturating at 2^15): the table at the top
** 8 fraction bits, then e^(r ln 2) = 1 + x + x^2/2 + x^3/6 for the rest
** (x < 2^-8) */
static inline NUM fx_exp2(int64_t y)
{
    if (y >= ((int64_t)15 << 30))
        return NUM_MAX;
    const int64_t ln2 = 744261118LL; /* ln 2 in 0.30 */
    if (y <= -((int64_t)20 << 30))
        return 0;                                   /* below 2^-17: rounds to 0 */
    int64_t ip = y >> 30;                           /* floor: arithmetic shift */
    int64_t f = y - ip * ((int64_t)1 << 30);        /* [0, 2^30) */
    int i = (int)(f >> 22);
    int64_t x = ((f & ((1 << 22) - 1)) * ln2) >> 30;
    int64_t x2 = (x * x) >> 30, x3 = (x2 * x) >> 30;
    int64_t e = ((int64_t)1 << 30) + x + x2 / 2 + x3 / 6;
    int64_t r = (fx_exp2_tab[i] * e + ((int64_t)1 << 29)) >> 30;   /* 2.30 */
    int sh = 14 - (int)ip;                          /* 2.30 -> 16.16, times 2^ip */
    if (sh <= 0)
        return num_sat(r);
    return num_sat((r + ((int64_t)1 << (sh - 1))) >> sh);
}

/* x^s for x >= 0 and s in [0, 128]; x > 1 occurs with unnormalised
** normals, and saturates rather than wraps */
static inline NUM num_pow(NUM x, NUM s)
{
    if (s == 0)
        return NUM_ONE;
    if (x <= 0)
        return 0;
    if (x == NUM_ONE)
        return NUM_ONE;
    int64_t l = fx_log2(x);                         /* 0.30 */
    int64_t p = (l * s) / 65536;                    /* 0.30, s in 16.16 */
    return fx_exp2(p);
}
#else
static inline NUM num_pow(NUM x, NUM s)
{
    if (s == 0)
        return 1;
    if (!(x > 0))
        return 0;
    return NUM_POW(x, s);
}
#endif
/* }==================================================================== */

/* {==================================================================== */
/* exp(-x) for x >= 0 (fog), through the same exp2 as num_pow */

#if NUM_IS_FIXED
static inline NUM num_exp_neg(NUM x)
{
    if (x <= 0)
        return NUM_ONE;
    /* -x * log2(e) in 0.30; log2(e) = 1.4426950408889634 as 2.30 */
    const int64_t log2e = 1549082005LL;
    return fx_exp2(-(((int64_t)x * log2e) >> 16));
}
#else
static inline NUM num_exp_neg(NUM x)
{
    return x <= 0 ? (NUM)1 : (NUM)exp(-(double)x);
}
#endif
/* }==================================================================== */

/* {==================================================================== */
/* Rasterizer weights and depth values */

#if NUM_IS_FIXED
typedef int32_t WGT;           /* 0.30 */
typedef int64_t DEPTHV;        /* depth units, 16 fraction bits */
#define WGT_BITS 30
#define WGT_ONE ((WGT)1 << 30)

/* a0*w0 + a1*w1 + a2*w2 with w in 0.30 summing to one */
static inline NUM wgt_lerp3(NUM a0, NUM a1, NUM a2, WGT w0, WGT w1, WGT w2)
{
    int64_t acc = (int64_t)a0 * w0 + (int64_t)a1 * w1 + (int64_t)a2 * w2;
    return num_from_scaled(acc, 46);
}

/* depth from vertex depths and linear weights, as an integer depth value */
static inline uint32_t wgt_depth3(DEPTHV z0, DEPTHV z1, DEPTHV z2, WGT w0, WGT w1, WGT w2, uint32_t maxval)
{
    /* z < 2^40 (24 integer + 16 fraction bits), w <= 2^30: one term < 2^70
    ** would overflow, so drop 12 fraction bits of z first (still 4 left). */
    int64_t acc = (z0 >> 12) * w0 + (z1 >> 12) * w1 + (z2 >> 12) * w2;
    int64_t v = (acc + ((int64_t)1 << 33)) >> 34;
    return (uint32_t)i64_clamp(v, 0, maxval);
}

static inline double depthv_to_double(DEPTHV z) { return (double)z / 65536.0; }

#else
typedef NUM WGT;
typedef NUM DEPTHV;
#define WGT_ONE ((NUM)1)

static inline NUM wgt_lerp3(NUM a0, NUM a1, NUM a2, WGT w0, WGT w1, WGT w2)
{
    return a0 * w0 + a1 * w1 + a2 * w2;
}

static inline uint32_t wgt_depth3(DEPTHV z0, DEPTHV z1, DEPTHV z2, WGT w0, WGT w1, WGT w2, uint32_t maxval)
{
    NUM v = z0 * w0 + z1 * w1 + z2 * w2;
    return (uint32_t)dbl_to_i64((double)v, 0, maxval);
}

static inline double depthv_to_double(DEPTHV z) { return (double)z; }

#endif
/* }==================================================================== */

/* {==================================================================== */
/* Clipping, projection and triangle weights */

#if NUM_IS_FIXED
typedef int64_t CLIPT;         /* intersection parameter in 0.30 */

/* t = dp / (dp - dq) for dp, dq of opposite signs (or one zero) */
static inline CLIPT num_clip_t(NUM dp, NUM dq)
{
    int64_t den = (int64_t)dp - dq;
    if (den == 0)
        return 0;
    return i64_clamp(i64_round_div((int64_t)dp * ((int64_t)1 << 30), den), 0, (int64_t)1 << 30);
}

static inline NUM num_lerp(NUM a, NUM b, CLIPT t)
{
    return num_sat((int64_t)a + num_from_scaled(((int64_t)b - a) * t, 46));
}

/* round(x / w * scale) for w > 0, as a 64-bit integer, clamped to
** +-NUM_PROJ_GUARD: a clipped vertex has |x / w| <= 1 and scale <= 2^19
** (half of MAX_VIEWPORT_DIMS in subpixels), so the clamp only holds the
** window coordinates of a vertex that non-finite input let past the clip
** tests to what the rasterizer's 64-bit edge arithmetic expects */
#define NUM_PROJ_GUARD ((int64_t)1 << 20)
static inline int64_t num_proj(NUM x, NUM w, int64_t scale)
{
    return i64_clamp(i64_round_div((int64_t)x * scale, w), -NUM_PROJ_GUARD, NUM_PROJ_GUARD);
}

/* window depth of clip z, w: (n + (f - n) * (z/w + 1) / 2) * maxval */
static inline DEPTHV depthv_from_clip(NUM z, NUM w, NUM n, NUM f, uint32_t maxval)
{
    int64_t one = (int64_t)1 << 30;
    int64_t zs = i64_clamp(i64_round_div((int64_t)z * one, w), -one, one);      /* 0.30 */
    int64_t n30 = (int64_t)n * 16384, f30 = (int64_t)f * 16384;                 /* 0.30 */
    int64_t d30 = n30 + (f30 - n30) * (zs + one) / (2 * one);
    d30 = i64_clamp(d30, 0, one);
    return (d30 * (int64_t)maxval + 8192) >> 14;                               /* 16 fraction bits */
}

/* Perspective-correct and linear barycentric weights from exact edge values.
** The linear weight of vertex i is e_i / area; the perspective one is
** (e_i / w_i) / sum_j (e_j / w_j). Only ratios of 1/w matter, so each 1/w is
** kept as a 30-bit mantissa and a shift, and products are aligned to the
** largest: no 16.16 reciprocal ever underflows near the far plane. */
typedef struct WgtSetup {
    int eshift;          /* e_i >> eshift fits in 31 bits; at most 32 (area2 < 2^63) */
    int64_t lin_recip;   /* 2^61 / (area >> eshift) */
    int64_t mant[3];     /* 1/w_i ~ mant_i * 2^-qshift_i (relative) */
    int qshift[3];
    int affine;          /* all w equal: perspective weights are linear */
} WgtSetup;

/* 1/w of a vertex as mant * 2^exp (relative scale: only ratios are used) */
typedef struct RecipW {
    int64_t mant;        /* 30 significant bits */
    int exp;
} RecipW;

static inline RecipW recipw_of(NUM w)
{
    RecipW q;
    int64_t r = ((int64_t)1 << 62) / (w > 0 ? w : 1);   /* 2^62 / w_raw */
    int rb = u64_bits((uint64_t)r) - 30;
    q.mant = rb > 0 ? r >> rb : r;
    q.exp = rb;
    return q;
}

static inline void wgt_setup(WgtSetup *s, int64_t area2, const NUM w[3], const RecipW q[3])
{
    int b = u64_bits((uint64_t)area2);
    s->eshift = b > 31 ? b - 31 : 0;
    s->lin_recip = ((int64_t)1 << 61) / (area2 >> s->eshift);
    s->affine = (w[0] == w[1] && w[1] == w[2]);
    int smax = q[0].exp > q[1].exp ? q[0].exp : q[1].exp;
    if (q[2].exp > smax)
        smax = q[2].exp;
    for (int i = 0; i < 3; i++) {
        s->mant[i] = q[i].mant;
        s->qshift[i] = smax - q[i].exp;
    }
}

static inline void wgt_linear(const WgtSetup *s, const int64_t e[3], WGT out[3])
{
    int64_t l1 = ((e[1] >> s->eshift) * s->lin_recip + ((int64_t)1 << 30)) >> 31;
    int64_t l2 = ((e[2] >> s->eshift) * s->lin_recip + ((int64_t)1 << 30)) >> 31;
    out[1] = (WGT)l1;
    out[2] = (WGT)l2;
    out[0] = (WGT)(WGT_ONE - l1 - l2);
}

/* What wgt_persp's division was at a fragment, for the level of detail's
** tangents (wgt_tangent): den (the sum of the numerators) scaled by 2^-sh
** into [2^31, 2^32) (sh < 0 scales up), and half = recip >> 1 for recip =
** round(2^62 / that), the reciprocal wgt_persp divides by wherever den >=
** 2^31; half 0 where the weights are the linear ones (affine, den <= 0) */
typedef struct WgtDen {
    uint32_t half;
    int32_t sh;
} WgtDen;

/* wgt_persp's weights from the numerators n_i >= 0 and their sum den > 0,
** and, where d is not NULL, its WgtDen */
static inline void wgt_persp_quotients(int64_t den, int64_t n1, int64_t n2, WGT out[3], WgtDen *d)
{
    int sh = u64_bits((uint64_t)den) - 32;
    if (sh > 0) {
        den >>= sh;
        n1 >>= sh;
        n2 >>= sh;
    }
    /* one division: n_i <= den < 2^32, so n_i * (2^62 / den) <= 2^62 */
    int64_t recip = (((int64_t)1 << 62) + den / 2) / den;
    int64_t p1 = (n1 * recip + ((int64_t)1 << 31)) >> 32;
    int64_t p2 = (n2 * recip + ((int64_t)1 << 31)) >> 32;
    out[1] = (WGT)p1;
    out[2] = (WGT)p2;
    out[0] = (WGT)(WGT_ONE - p1 - p2);
    if (!d)
        return;
    if (den >= ((int64_t)1 << 31)) {
        d->half = (uint32_t)(recip >> 1);
        d->sh = sh > 0 ? sh : 0;
    } else {
        /* (a small den, wgt_persp's shift 0): scaled up into range, with a
        ** reciprocal of its own */
        const int up = 32 - u64_bits((uint64_t)den);
        const int64_t dn = den << up;
        d->half = (uint32_t)(((((int64_t)1 << 62) + dn / 2) / dn) >> 1);
        d->sh = -up;
    }
}

/* wgt_persp, with its WgtDen where d is not NULL */
static inline void wgt_persp_den(const WgtSetup *s, const int64_t e[3], WGT out[3], WgtDen *d)
{
    if (d)
        *d = (WgtDen){ 0, 0 };
    if (s->affine) {
        wgt_linear(s, e, out);
        return;
    }
    int64_t n[3], den = 0;
    for (int i = 0; i < 3; i++) {
        int sh = s->qshift[i];
        n[i] = sh < 63 ? ((e[i] >> s->eshift) * s->mant[i]) >> sh : 0;
        den += n[i];
    }
    if (den <= 0) {
        wgt_linear(s, e, out);
        return;
    }
    wgt_persp_quotients(den, n[1], n[2], out, d);
}

static inline void wgt_persp(const WgtSetup *s, const int64_t e[3], WGT out[3]) { wgt_persp_den(s, e, out, NULL); }

/* The level of detail's neighbours (ES 1.1 §3.7.7): the perspective
** weights' tangent one pixel along an edge step d (t->ea right, t->eb up),
** p_i + dp_i with dp_i = (a_i - p_i sum_j a_j) / den, a_i = d_i / w_i:
** the derivative at the fragment, which the spec's du/dx asks for, where a
** difference with the neighbour's weights would be a secant. */
typedef struct WgtTangent {
    int32_t a[3];      /* a_i = ((d_i >> eshift) mant_i) >> qshift_i, scaled by 2^-ashift below 2^29 */
    int32_t asum;      /* their sum */
    int32_t ashift;    /* the same for both steps of a triangle */
    int32_t lin[3];    /* the linear weights' step d_i / area in 2^-30, within +-(2^31 - 1) */
} WgtTangent;

/* floor(n / 2^k) for k >= 0 (0 or -1 from k = 63 on) */
static inline int64_t i64_floor_shift(int64_t n, int k)
{
    if (k > 62)
        return n < 0 ? -1 : 0;
    return n < 0 ? -(int64_t)((((uint64_t)0 - (uint64_t)n) + (((uint64_t)1 << k) - 1)) >> k) : n >> k;
}

/* WgtTangent of the edge steps ea (g[0]) and eb (g[1]) for a triangle of
** twice the area area2 > 0 */
static inline void wgt_tangents_setup(const WgtSetup *s, int64_t area2, const int64_t ea[3], const int64_t eb[3],
                                      WgtTangent g[2])
{
    const int64_t lim = ((int64_t)1 << 31) - 1, big = (int64_t)1 << 31;
    const int64_t area = area2 >> s->eshift > 0 ? area2 >> s->eshift : 1;
    int64_t a[2][3];
    uint64_t top = 0;
    for (int k = 0; k < 2; k++)
        for (int i = 0; i < 3; i++) {
            const int64_t x = i64_clamp(i64_div_pow2((k ? eb : ea)[i], s->eshift), -big, big);
            const int sh = s->qshift[i] < 62 ? s->qshift[i] : 62;
            a[k][i] = s->affine ? 0 : i64_div_pow2(x * s->mant[i], sh);     /* |a_i| < 2^61 */
            const uint64_t m = a[k][i] < 0 ? (uint64_t)0 - (uint64_t)a[k][i] : (uint64_t)a[k][i];
            top = m > top ? m : top;
            /* |x| < 2 area: x 2^30 < 2^62 */
            g[k].lin[i] = (int32_t)(x >= 2 * area    ? lim
                                    : x <= -2 * area ? -lim
                                                     : i64_clamp(i64_round_div(x * ((int64_t)1 << 30), area), -lim, lim));
        }
    const int ashift = u64_bits(top) > 29 ? u64_bits(top) - 29 : 0;
    for (int k = 0; k < 2; k++) {
        g[k].ashift = ashift;
        g[k].asum = 0;
        for (int i = 0; i < 3; i++) {
            g[k].a[i] = (int32_t)i64_div_pow2(a[k][i], ashift);
            g[k].asum += g[k].a[i];
        }
    }
}

/* the tangent weights out of weights p at a fragment whose division was d
** (WgtDen): the numerator n_i = a_i - floor((p_i sum_j a_j + 2^29) / 2^30)
** (in units of 2^ashift), and with k = sh - ashift, dp_i = floor((floor(n_i
** 2^-k) half + 2^30) / 2^31) for k >= 0, floor((n_i half + 2^(30 + k)) /
** 2^(31 + k)) for -30 <= k < 0 (n_i 2^-k half / 2^31 rounded once), +-2^62
** below (a derivative past 2^30 weights a pixel); the linear step where
** d.half is 0. Each weight is kept within +-(2^31 - 1), out[0] = 1 - out[1]
** - out[2]. */
static inline void wgt_tangent(const WgtTangent *g, const WGT p[3], WgtDen d, WGT out[3])
{
    const int64_t lim = ((int64_t)1 << 31) - 1;
    int64_t dp[3] = { 0, g->lin[1], g->lin[2] };
    if (d.half) {
        const int k = d.sh - g->ashift;
        for (int i = 1; i < 3; i++) {
            const int64_t n = g->a[i] - i64_floor_div((int64_t)p[i] * g->asum + ((int64_t)1 << 29), (int64_t)1 << 30);
            if (k >= 0)
                dp[i] = i64_floor_div(i64_floor_shift(n, k) * (int64_t)d.half + ((int64_t)1 << 30), (int64_t)1 << 31);
            else if (k >= -30)
                dp[i] = i64_floor_div(n * (int64_t)d.half + ((int64_t)1 << (30 + k)), (int64_t)1 << (31 + k));
            else
                dp[i] = n == 0 ? 0 : (n < 0 ? -((int64_t)1 << 62) : (int64_t)1 << 62);
        }
    }
    const int64_t o1 = i64_clamp(p[1] + dp[1], -lim, lim), o2 = i64_clamp(p[2] + dp[2], -lim, lim);
    out[1] = (WGT)o1;
    out[2] = (WGT)o2;
    out[0] = (WGT)i64_clamp(WGT_ONE - o1 - o2, -lim, lim);
}

#else
typedef NUM CLIPT;

static inline CLIPT num_clip_t(NUM dp, NUM dq)
{
    NUM den = dp - dq;
    if (den == 0)
        return 0;
    NUM t = dp / den;
    return t < 0 ? 0 : (t > 1 ? 1 : t);
}

static inline NUM num_lerp(NUM a, NUM b, CLIPT t) { return a + (b - a) * t; }

#define NUM_PROJ_GUARD ((int64_t)1 << 20)      /* as the fixed build's */

static inline int64_t num_proj(NUM x, NUM w, int64_t scale)
{
    /* ties away from zero, as the fixed build's i64_round_div: every build
    ** snaps a vertex exactly between two subpixels to the same one */
    /* clamped as the fixed build's (NaN gives 0) */
    double v = (double)((x / w) * (NUM)scale);
    return v < 0 ? -dbl_to_i64(-v, 0, NUM_PROJ_GUARD) : dbl_to_i64(v, 0, NUM_PROJ_GUARD);
}

static inline DEPTHV depthv_from_clip(NUM z, NUM w, NUM n, NUM f, uint32_t maxval)
{
    NUM zs = z / w;
    zs = zs < -1 ? -1 : (zs > 1 ? 1 : zs);
    NUM d = n + (f - n) * (zs + 1) * (NUM)0.5;
    d = d < 0 ? 0 : (d > 1 ? 1 : d);
    return d * (NUM)maxval;
}

typedef struct WgtSetup {
    NUM inv_area;
    NUM q[3];
    int affine;
} WgtSetup;

typedef NUM RecipW;

static inline RecipW recipw_of(NUM w) { return (NUM)1 / w; }

static inline void wgt_setup(WgtSetup *s, int64_t area2, const NUM w[3], const RecipW q[3])
{
    s->inv_area = (NUM)1 / (NUM)area2;
    s->affine = (w[0] == w[1] && w[1] == w[2]);
    for (int i = 0; i < 3; i++)
        s->q[i] = q[i];
}

static inline void wgt_linear(const WgtSetup *s, const int64_t e[3], WGT out[3])
{
    out[1] = (NUM)e[1] * s->inv_area;
    out[2] = (NUM)e[2] * s->inv_area;
    out[0] = 1 - out[1] - out[2];
}

/* wgt_persp's 1/den (WgtDen; 0 where the weights are linear, affine) */
typedef NUM WgtDen;

static inline void wgt_persp_den(const WgtSetup *s, const int64_t e[3], WGT out[3], WgtDen *d)
{
    if (s->affine) {
        wgt_linear(s, e, out);
        if (d)
            *d = 0;
        return;
    }
    NUM n0 = (NUM)e[0] * s->q[0], n1 = (NUM)e[1] * s->q[1], n2 = (NUM)e[2] * s->q[2];
    NUM inv = (NUM)1 / (n0 + n1 + n2);
    out[1] = n1 * inv;
    out[2] = n2 * inv;
    out[0] = 1 - out[1] - out[2];
    if (d)
        *d = inv;
}

static inline void wgt_persp(const WgtSetup *s, const int64_t e[3], WGT out[3]) { wgt_persp_den(s, e, out, NULL); }

/* as the fixed build's WgtTangent: a_i = d_i / w_i, the linear step d_i / area */
typedef struct WgtTangent {
    NUM a[3];
    NUM lin[3];
    int affine;
} WgtTangent;

static inline void wgt_tangents_setup(const WgtSetup *s, int64_t area2, const int64_t ea[3], const int64_t eb[3],
                                      WgtTangent g[2])
{
    (void)area2;
    for (int k = 0; k < 2; k++) {
        g[k].affine = s->affine;
        for (int i = 0; i < 3; i++) {
            g[k].a[i] = (NUM)(k ? eb : ea)[i] * s->q[i];
            g[k].lin[i] = (NUM)(k ? eb : ea)[i] * s->inv_area;
        }
    }
}

/* the tangent weights: dp_i = a_i / den - p_i r, r = sum_j a_j / den (the
** linear step where the triangle is affine) */
static inline void wgt_tangent(const WgtTangent *g, const WGT p[3], WgtDen inv, WGT out[3])
{
    NUM d1 = g->lin[1], d2 = g->lin[2];
    if (!g->affine) {
        const NUM a0 = g->a[0] * inv, a1 = g->a[1] * inv, a2 = g->a[2] * inv;
        const NUM r = a0 + a1 + a2;
        d1 = a1 - p[1] * r;
        d2 = a2 - p[2] * r;
    }
    out[1] = p[1] + d1;
    out[2] = p[2] + d2;
    out[0] = 1 - out[1] - out[2];
}
#endif

/* wgt_persp's weights p at edge values e and, where g is not NULL, their
** tangents along g[0] (tx) and g[1] (ty) from the same division */
static inline void wgt_persp_tangents(const WgtSetup *s, const WgtTangent g[2], const int64_t e[3], WGT p[3],
                                      WGT tx[3], WGT ty[3])
{
    WgtDen den;
    wgt_persp_den(s, e, p, g ? &den : NULL);
    if (!g)
        return;
    wgt_tangent(&g[0], p, den, tx);
    wgt_tangent(&g[1], p, den, ty);
}
/* }==================================================================== */

/* {==================================================================== */
/* Fragment colour arithmetic (FRAGV): texture environments, fog, alpha
** test and blending. The fixed build works in signed 0.30 in an int64, with
** headroom for the ranges COMBINE reaches (scale 4, ADD_SIGNED, DOT3):
** colours interpolate straight into 0.30 from the exact weights, a texel or
** framebuffer value d becomes d/max with an error under 2^-31, and the
** result rounds once to the framebuffer's bits. So a modulation of two
** 8-bit values rounds to nearest exactly, and 255 * 255 stays 255. Other
** builds use NUM. */

#if NUM_IS_FIXED
typedef int64_t FRAGV;
#define FRAG_ONE ((int64_t)1 << 30)
static inline FRAGV frag_from_num(NUM a) { return (int64_t)a * 16384; }
static inline FRAGV frag_from_unorm(uint32_t d, uint32_t maxval)
{
    return (int64_t)((((uint64_t)d << 31) / maxval + 1) >> 1);
}
static inline FRAGV frag_mul(FRAGV a, FRAGV b) { return (a * b + ((int64_t)1 << 29)) >> 30; }
static inline FRAGV frag_min(FRAGV a, FRAGV b) { return a < b ? a : b; }
/* round(v * maxval) clamped to [0, maxval]; t in [0,1) as 0.30 is the
** dither threshold (1/2 rounds to nearest) */
static inline uint32_t frag_to_unorm(FRAGV v, uint32_t maxval, FRAGV t)
{
    if (v <= 0)
        return 0;
    if (v >= FRAG_ONE)
        return maxval;
    return (uint32_t)((v * maxval + t) >> 30);
}
static inline FRAGV frag_ratio(int n, int d) { return ((int64_t)n << 30) / d; }
/* floor(v * 2^bits), clamped: keeps the high bits of an exact c/255 */
static inline uint32_t frag_to_msb(FRAGV v, int bits)
{
    if (v <= 0)
        return 0;
    int64_t r = v >> (30 - bits);
    return (uint32_t)(r >= ((int64_t)1 << bits) ? ((int64_t)1 << bits) - 1 : r);
}
static inline FRAGV frag_from_double(double v) { return dbl_to_i64(v * 1073741824.0, -((int64_t)1 << 40), (int64_t)1 << 40); }
static inline FRAGV frag_clamp01(FRAGV v) { return v < 0 ? 0 : (v > FRAG_ONE ? FRAG_ONE : v); }
/* a0*w0 + a1*w1 + a2*w2 from 16.16 values and 0.30 weights, kept in 0.30 */
static inline FRAGV frag_lerp3(NUM a0, NUM a1, NUM a2, WGT w0, WGT w1, WGT w2)
{
    int64_t acc = (int64_t)a0 * w0 + (int64_t)a1 * w1 + (int64_t)a2 * w2;   /* 46 fraction bits */
    return acc >= 0 ? (acc + 32768) >> 16 : -((-acc + 32768) >> 16);
}

/* the same for colours already in 0.30 (each within [0,1], so every term
** stays below 2^60) */
static inline FRAGV frag_lerp3f(FRAGV a0, FRAGV a1, FRAGV a2, WGT w0, WGT w1, WGT w2)
{
    int64_t acc = a0 * w0 + a1 * w1 + a2 * w2;                              /* 60 fraction bits */
    return acc >= 0 ? (acc + ((int64_t)1 << 29)) >> 30 : -((-acc + ((int64_t)1 << 29)) >> 30);
}

/* a + (b - a) t for a clip parameter t in 0.30 */
static inline FRAGV frag_lerp_clip(FRAGV a, FRAGV b, CLIPT t) { return a + (((b - a) * t + ((int64_t)1 << 29)) >> 30); }
#else
typedef NUM FRAGV;
#define FRAG_ONE ((NUM)1)
static inline FRAGV frag_from_num(NUM a) { return a; }
static inline FRAGV frag_from_unorm(uint32_t d, uint32_t maxval) { return (NUM)d / (NUM)maxval; }
static inline FRAGV frag_mul(FRAGV a, FRAGV b) { return a * b; }
static inline FRAGV frag_min(FRAGV a, FRAGV b) { return a < b ? a : b; }
static inline uint32_t frag_to_unorm(FRAGV v, uint32_t maxval, FRAGV t)
{
    if (!(v > 0))
        return 0;
    if (v >= 1)
        return maxval;
    return (uint32_t)(v * (NUM)maxval + t);
}
static inline FRAGV frag_ratio(int n, int d) { return (NUM)n / (NUM)d; }
static inline uint32_t frag_to_msb(FRAGV v, int bits)
{
    if (!(v > 0))
        return 0;
    NUM r = NUM_FLOOR(v * (NUM)(1 << bits));
    return r >= (NUM)(1 << bits) ? (1u << bits) - 1 : (uint32_t)r;
}
static inline FRAGV frag_from_double(double v) { return (NUM)v; }
static inline FRAGV frag_clamp01(FRAGV v) { return v < 0 ? 0 : (v > 1 ? 1 : v); }
static inline FRAGV frag_lerp3(NUM a0, NUM a1, NUM a2, WGT w0, WGT w1, WGT w2)
{
    return a0 * w0 + a1 * w1 + a2 * w2;
}

static inline FRAGV frag_lerp3f(FRAGV a0, FRAGV a1, FRAGV a2, WGT w0, WGT w1, WGT w2)
{
    return a0 * w0 + a1 * w1 + a2 * w2;
}

static inline FRAGV frag_lerp_clip(FRAGV a, FRAGV b, CLIPT t) { return a + (b - a) * t; }
#endif
/* }==================================================================== */

/* {==================================================================== */
/* Texture coordinates at a pixel (TEXC) and the level of detail (LODV).
** The fixed build interpolates s, t, q into 32 fraction bits (int64) from
** the exact weights, so coordinates up to +-2^30 keep 32 fraction bits:
** REPEAT then wraps exactly before scaling to texel space, and a 2048-texel
** texture still gets 21 bits of sub-texel position. LODV is log2 in 0.30.
** Other builds use NUM for both. */

#if NUM_IS_FIXED
typedef int64_t TEXC;
typedef int64_t LODV;
#define TEXC_ONE ((int64_t)1 << 32)
#define LODV_ONE ((int64_t)1 << 30)

static inline TEXC texc_lerp3(NUM a0, NUM a1, NUM a2, WGT w0, WGT w1, WGT w2)
{
    int64_t acc = (int64_t)a0 * w0 + (int64_t)a1 * w1 + (int64_t)a2 * w2;   /* 46 fraction bits */
    return acc >= 0 ? (acc + 8192) >> 14 : -((-acc + 8192) >> 14);
}

/* s / q, both with 32 fraction bits; saturates beyond +-2^30 */
static inline TEXC texc_div(TEXC s, TEXC q)
{
    if (q == 0)
        return s > 0 ? ((int64_t)1 << 62) : (s < 0 ? -((int64_t)1 << 62) : 0);
    /* long division 16 bits at a time: |q| < 2^47, so the remainders
    ** shifted by 16 stay below 2^63 */
    if (q > ((int64_t)1 << 46) || q < -((int64_t)1 << 46)) {
        s /= 65536;
        q /= 65536;
        if (q == 0)
            return 0;
    }
    int64_t a = s / q, r = s % q;
    if (a > ((int64_t)1 << 30) || a < -((int64_t)1 << 30))
        return a > 0 ? ((int64_t)1 << 62) : -((int64_t)1 << 62);
    int64_t a1 = (r * 65536) / q;
    r = (r * 65536) % q;
    int64_t a2 = (r * 65536) / q;
    return a * TEXC_ONE + a1 * 65536 + a2;
}

static inline TEXC texc_floor(TEXC s) { return (s >> 32) * TEXC_ONE; }
static inline int64_t texc_ifloor(TEXC s) { return s >> 32; }
/* (a + 1) / 2, the cube map face coordinate of a in [-1, 1] (|a| <= 2^62) */
static inline TEXC texc_unit_half(TEXC a) { return (a + TEXC_ONE) / 2; }
static inline TEXC texc_abs(TEXC a) { return a < 0 ? -a : a; }
static inline TEXC texc_clamp(TEXC a, TEXC lim) { return a < -lim ? -lim : (a > lim ? lim : a); }
/* anisotropic footprints: ceil(a / b) of positives below 2^62, a / n,
** a * num / den rounded (|a| <= 2^51, |num| <= 2^10) */
static inline int64_t texc_ceil_ratio(TEXC a, TEXC b) { return (a + b - 1) / b; }
static inline TEXC texc_div_int(TEXC a, int n) { return a / n; }
static inline TEXC texc_mul_ratio(TEXC a, int num, int den)
{
    const int64_t p = a * num;
    return p >= 0 ? (p + den / 2) / den : -((-p + den / 2) / den);
}
/* n >= 1 summed colours (each in [0, 1]) averaged, rounded */
static inline FRAGV frag_div_int(FRAGV sum, int n) { return (sum + n / 2) / n; }
/* n / d for integers (|n| < 2^31, d > 0) */
static inline TEXC texc_ratio(int64_t n, int64_t d) { return d ? (n * TEXC_ONE) / d : 0; }
static inline TEXC texc_from_double(double v) { return dbl_to_i64(v * 4294967296.0, -((int64_t)1 << 62), (int64_t)1 << 62); }
/* a * n for an integer n (texture size): exact */
static inline TEXC texc_scale(TEXC a, int n) { return a * n; }
/* bilinear weights: the fraction of a texel coordinate in 16 bits */
typedef int32_t TEXW;
static inline TEXW texc_frac_weight(TEXC u) { return (int32_t)((u >> 16) & 0xFFFF); }

/* Bilinear filtering of four RGBA8888 texels: the weighted sum of the 8-bit
** values (weights sum to 2^32), then one conversion to 0.30 through
** 2^32 / 255 = 16843009 (relative error 2^-32), so a texel c gives c/255
** to 2^-31 and blends round once. */
static inline void frag_bilerp_rgba8(uint32_t c00, uint32_t c10, uint32_t c01, uint32_t c11, TEXW a, TEXW b,
                                     FRAGV out[4], const FRAGV *unorm)
{
    (void)unorm;
    uint64_t ia = 65536 - (uint64_t)a, ib = 65536 - (uint64_t)b;
    uint64_t w00 = ia * ib, w10 = (uint64_t)a * ib, w01 = ia * (uint64_t)b, w11 = (uint64_t)a * (uint64_t)b;
    for (int k = 0; k < 4; k++) {
        int sh = 8 * k;
        uint64_t acc = ((c00 >> sh) & 0xFF) * w00 + ((c10 >> sh) & 0xFF) * w10 + ((c01 >> sh) & 0xFF) * w01
                     + ((c11 >> sh) & 0xFF) * w11;                 /* c8 with 32 fraction bits, < 2^40 */
        out[k] = (FRAGV)((((acc + 128) >> 8) * 16843009u + ((uint64_t)1 << 25)) >> 26);
    }
}
#define TEXC_HALF ((int64_t)1 << 31)

/* log2 of a positive texel-space derivative, in 0.30; 0 gives -2^40 */
static inline LODV lod_log2(TEXC rho)
{
    if (rho <= 0)
        return -((int64_t)1 << 40);
    int64_t r = rho >> 16;                         /* to 16.16 */
    if (r == 0)
        return -((int64_t)17 << 30);               /* below 2^-16 */
    if (r > INT32_MAX)
        r = INT32_MAX;
    return fx_log2((int32_t)r);
}
static inline LODV lod_from_ratio(int n, int d) { return ((int64_t)n << 30) / d; }
/* a real level-of-detail offset (|v| <= 2^20) in 0.30 */
static inline LODV lod_from_double(double v) { return dbl_to_i64(v * 1073741824.0, -((int64_t)1 << 50), (int64_t)1 << 50); }
static inline int64_t lod_ifloor(LODV l) { return l >> 30; }
static inline FRAGV lod_frac(LODV l) { return l & (((int64_t)1 << 30) - 1); }
#else
typedef NUM TEXC;
typedef NUM LODV;
#define TEXC_ONE ((NUM)1)
#define LODV_ONE ((NUM)1)
#define TEXC_HALF ((NUM)0.5)

static inline TEXC texc_lerp3(NUM a0, NUM a1, NUM a2, WGT w0, WGT w1, WGT w2)
{
    return a0 * w0 + a1 * w1 + a2 * w2;
}
static inline TEXC texc_div(TEXC s, TEXC q) { return q == 0 ? (s > 0 ? (NUM)1e30 : (s < 0 ? (NUM)-1e30 : 0)) : s / q; }
static inline TEXC texc_floor(TEXC s) { return NUM_FLOOR(s); }
static inline TEXC texc_unit_half(TEXC a) { return (a + 1) * (NUM)0.5; }
static inline int64_t texc_ifloor(TEXC s) { return dbl_to_i64(floor((double)s), -((int64_t)1 << 40), (int64_t)1 << 40); }
static inline TEXC texc_abs(TEXC a) { return a < 0 ? -a : a; }
static inline TEXC texc_clamp(TEXC a, TEXC lim) { return a < -lim ? -lim : (a > lim ? lim : a); }
static inline int64_t texc_ceil_ratio(TEXC a, TEXC b)
{
    const double r = ceil((double)a / (double)b);
    return r > 1e9 ? (int64_t)1e9 : (int64_t)r;
}
static inline TEXC texc_div_int(TEXC a, int n) { return a / (NUM)n; }
static inline TEXC texc_mul_ratio(TEXC a, int num, int den) { return a * (NUM)num / (NUM)den; }
static inline FRAGV frag_div_int(FRAGV sum, int n) { return sum / (NUM)n; }
static inline TEXC texc_ratio(int64_t n, int64_t d) { return d ? (NUM)n / (NUM)d : 0; }
static inline TEXC texc_from_double(double v) { return (NUM)v; }
static inline TEXC texc_scale(TEXC a, int n) { return a * (NUM)n; }
typedef NUM TEXW;
static inline TEXW texc_frac_weight(TEXC u) { return u - NUM_FLOOR(u); }

static inline void frag_bilerp_rgba8(uint32_t c00, uint32_t c10, uint32_t c01, uint32_t c11, TEXW a, TEXW b,
                                     FRAGV out[4], const FRAGV *unorm)
{
    for (int k = 0; k < 4; k++) {
        int sh = 8 * k;
        FRAGV v00 = unorm[(c00 >> sh) & 0xFF], v10 = unorm[(c10 >> sh) & 0xFF];
        FRAGV v01 = unorm[(c01 >> sh) & 0xFF], v11 = unorm[(c11 >> sh) & 0xFF];
        out[k] = (v00 * (1 - a) + v10 * a) * (1 - b) + (v01 * (1 - a) + v11 * a) * b;
    }
}

/* the float and double builds' log2 of rho (below): a row's c and -log2(c)
** rounded to nearest, the series' coefficients */
static const double lod_log2_c[128] = {
    0x1p+0, 0x1.fa11cp-1, 0x1.f631p-1, 0x1.f25f8p-1, 0x1.ee9c8p-1, 0x1.eae8p-1,
    0x1.e741cp-1, 0x1.e3a9p-1, 0x1.e01ep-1, 0x1.dcap-1, 0x1.d92f4p-1, 0x1.d5cacp-1,
    0x1.d272cp-1, 0x1.cf27p-1, 0x1.cbe6cp-1, 0x1.c8b28p-1, 0x1.c5894p-1, 0x1.c26b4p-1,
    0x1.bf584p-1, 0x1.bc4fcp-1, 0x1.b952p-1, 0x1.b65e4p-1, 0x1.b3748p-1, 0x1.b094cp-1,
    0x1.adbe8p-1, 0x1.aaf1cp-1, 0x1.a82e8p-1, 0x1.a574p-1, 0x1.a2c2cp-1, 0x1.a01ap-1,
    0x1.9d7ap-1, 0x1.9ae24p-1, 0x1.9853p-1, 0x1.95cbcp-1, 0x1.934c8p-1, 0x1.90d5p-1,
    0x1.8e654p-1, 0x1.8bfdp-1, 0x1.899cp-1, 0x1.87428p-1, 0x1.84fp-1, 0x1.82a4cp-1,
    0x1.806p-1, 0x1.7e224p-1, 0x1.7beb4p-1, 0x1.79bacp-1, 0x1.77908p-1, 0x1.756ccp-1,
    0x1.734fp-1, 0x1.71378p-1, 0x1.6f26p-1, 0x1.6d1a8p-1, 0x1.6b148p-1, 0x1.69148p-1,
    0x1.671ap-1, 0x1.6525p-1, 0x1.63358p-1, 0x1.614b4p-1, 0x1.5f664p-1, 0x1.5d868p-1,
    0x1.5babcp-1, 0x1.59d6p-1, 0x1.58058p-1, 0x1.56398p-1, 0x1.54726p+0, 0x1.52bp+0,
    0x1.50f22p+0, 0x1.4f39p+0, 0x1.4d844p+0, 0x1.4bd3ep+0, 0x1.4a28p+0, 0x1.48806p+0,
    0x1.46dcep+0, 0x1.453dap+0, 0x1.43a28p+0, 0x1.420b6p+0, 0x1.40782p+0, 0x1.3ee9p+0,
    0x1.3d5dap+0, 0x1.3bd6p+0, 0x1.3a524p+0, 0x1.38d22p+0, 0x1.3755cp+0, 0x1.35dcep+0,
    0x1.3467ap+0, 0x1.32f5cp+0, 0x1.31878p+0, 0x1.301c8p+0, 0x1.2eb4ep+0, 0x1.2d50ap+0,
    0x1.2befap+0, 0x1.2a91cp+0, 0x1.29372p+0, 0x1.27dfap+0, 0x1.268b4p+0, 0x1.2539ep+0,
    0x1.23eb8p+0, 0x1.22a02p+0, 0x1.2157ap+0, 0x1.2012p+0, 0x1.1ecf4p+0, 0x1.1d8f6p+0,
    0x1.1c522p+0, 0x1.1b17cp+0, 0x1.19e02p+0, 0x1.18abp+0, 0x1.1778ap+0, 0x1.1648ep+0,
    0x1.151bap+0, 0x1.13f0ep+0, 0x1.12c8cp+0, 0x1.11a3p+0, 0x1.107fcp+0, 0x1.0f5eep+0,
    0x1.0e406p+0, 0x1.0d244p+0, 0x1.0c0a8p+0, 0x1.0af3p+0, 0x1.09ddcp+0, 0x1.08cacp+0,
    0x1.07bap+0, 0x1.06ab6p+0, 0x1.059eep+0, 0x1.0494ap+0, 0x1.038c6p+0, 0x1.02864p+0,
    0x1.01824p+0, 0x1p+0,
};
static const double lod_log2_l[128] = {
    0x0p+0, 0x1.136501c41be5bp-6, 0x1.c938377c791ebp-6, 0x1.3ed07768252e6p-5,
    0x1.985bf0a9f1682p-5, 0x1.f13950dd61d4bp-5, 0x1.24b4b14f2f5a6p-4, 0x1.507ca3ea37377p-4,
    0x1.7bef0080d198dp-4, 0x1.a7128f47ca26ap-4, 0x1.d1e1d9fea4a74p-4, 0x1.fc6705edc941dp-4,
    0x1.134e5c3469e6p-3, 0x1.2841ed563983dp-3, 0x1.3d11e9dff5602p-3, 0x1.51ba0ecabc26p-3,
    0x1.663fc4cb09b06p-3, 0x1.7aa06ce365cafp-3, 0x1.8edca74cac696p-3, 0x1.a2f6c6cb0ade9p-3,
    0x1.b6ec2d4121066p-3, 0x1.cac0ec0910ecep-3, 0x1.de741df856d7bp-3, 0x1.f204db90ea104p-3,
    0x1.02bad58e156f8p-2, 0x1.0c62d8f9c725fp-2, 0x1.15fa09a5417eep-2, 0x1.1f829922bc7ebp-2,
    0x1.28fa6066bc28ep-2, 0x1.32639bfc045f8p-2, 0x1.3bbd061a3e15cp-2, 0x1.4508049660cb4p-2,
    0x1.4e43513c072acp-2, 0x1.57705a2804cc9p-2, 0x1.608ec34176f83p-2, 0x1.699f1b7644bfap-2,
    0x1.72a109519ff57p-2, 0x1.7b952152a8b97p-2, 0x1.847bfcf2b9b65p-2, 0x1.8d54575cbb376p-2,
    0x1.961fbe7d038ccp-2, 0x1.9edced7156575p-2, 0x1.a78e70c49c66ap-2, 0x1.b03210812ca03p-2,
    0x1.b8c8730eee185p-2, 0x1.c15243ef36537p-2, 0x1.c9d033c0a1dfdp-2, 0x1.d240fde0460eep-2,
    0x1.daa6532d9d83p-2, 0x1.e2feef39dc32cp-2, 0x1.eb4b8a4267991p-2, 0x1.f38bdebd6ed19p-2,
    0x1.fbc1af5ea9c83p-2, 0x1.01f55937e0a5dp-1, 0x1.060457a7350e3p-1, 0x1.0a0db370ed35dp-1,
    0x1.0e114cc59d587p-1, 0x1.120f89639869bp-1, 0x1.16084b23af3a9p-1, 0x1.19fb739fe1c24p-1,
    0x1.1de96c2e11a1ep-1, 0x1.21d218189d97bp-1, 0x1.25b4d1044b09bp-1, 0x1.29931606ec643p-1,
    -0x1.a52804704ebdfp-2, -0x1.9d809ce727336p-2, -0x1.95e2bc0842f9p-2, -0x1.8e4faf41f99a4p-2,
    -0x1.86c6057689e8ap-2, -0x1.7f45f0ac055cap-2, -0x1.77d0327c430a7p-2, -0x1.7063e00b7efb5p-2,
    -0x1.690099b9cb3d9p-2, -0x1.61a72016673a9p-2, -0x1.5a5712c9f6a2fp-2, -0x1.53100ef4ada69p-2,
    -0x1.4bd1af2c86ce2p-2, -0x1.449d483180645p-2, -0x1.3d714c1360ce5p-2, -0x1.364de59746cebp-2,
    -0x1.2f33d63ac6a69p-2, -0x1.28221d505ffb7p-2, -0x1.21197c3be990dp-2, -0x1.1a18eddf22e2dp-2,
    -0x1.1321337e2905bp-2, -0x1.0c31438428a13p-2, -0x1.054a79ca7c3bep-2, -0x1.fcd65dedbc12cp-3,
    -0x1.ef2847fa56d2dp-3, -0x1.e18b002886e8ap-3, -0x1.d3fd9a32ca6c6p-3, -0x1.c67f24933fe3ap-3,
    -0x1.b91124bbb16f6p-3, -0x1.abb2a74631be2p-3, -0x1.9e63f4853f27dp-3, -0x1.912412d5af6a5p-3,
    -0x1.83f3472af22e8p-3, -0x1.76d1d6efa8d9bp-3, -0x1.69bec13e5da46p-3, -0x1.5cba4815d2768p-3,
    -0x1.4fc4ade5d274cp-3, -0x1.42de358d334cap-3, -0x1.36048942ccde3p-3, -0x1.293a800d97e62p-3,
    -0x1.1c7f0ea0d9b1dp-3, -0x1.0fcfd373a57eap-3, -0x1.032fab179b79bp-3, -0x1.ed3b0592f5c51p-4,
    -0x1.d43084c62ed7dp-4, -0x1.bb4045fae9a73p-4, -0x1.a26d6c4bca3b3p-4, -0x1.89b30df1ebccdp-4,
    -0x1.71144c9812025p-4, -0x1.588ee483c3392p-4, -0x1.402342d6b031ep-4, -0x1.27d1d5617338p-4,
    -0x1.0f9b0aa0a6ecap-4, -0x1.eef91aba429ep-5, -0x1.beed897667a79p-5, -0x1.8f143105da0b3p-5,
    -0x1.5f6de23af4cf7p-5, -0x1.2ff5cf561236fp-5, -0x1.00acba4e8a4c3p-5, -0x1.a3322351dbeacp-6,
    -0x1.4560919e9ccd5p-6, -0x1.cfe32b6199e97p-7, -0x1.15cd79ac60bbbp-7, 0x0p+0,
};
/* (-1)^(k+1) / (k ln 2), the series of log2(1 + r) */
#define LOD_LOG2_A1 0x1.71547652b82fep+0
#define LOD_LOG2_A2 (-0x1.71547652b82fep-1)
#define LOD_LOG2_A3 0x1.ec709dc3a03fdp-2
#define LOD_LOG2_A4 (-0x1.71547652b82fep-2)
#define LOD_LOG2_A5 0x1.2776c50ef9bfep-2
#define LOD_LOG2_A6 (-0x1.ec709dc3a03fdp-3)

typedef union LodBits { double d; uint64_t u; } LodBits;

#if defined(GLES_NUM_FLOAT)
/* The float build's lambda is (float)log2((double)rho). Rather than a libm
** call per fragment, y = lod_log2_approx(rho) in double, and (float)y
** wherever no float rounding boundary (the midpoint of two adjacent floats)
** lies within 2^12 ulps of y; elsewhere (about one in 2^16) log2 itself.
**
** The approximation, for a positive finite x = (double)rho (whose
** significand has at most 24 bits): x = 2^e m with m in [0.75, 1.5) (the
** top 7 bits of the significand pick a table row; rows 64..127 take m / 2
** and e + 1); r = m c - 1 with c = lod_log2_c[row] a multiple of 2^-19
** (20 bits) near 1 / m, so m c is exact (at most 44 bits) and so is the
** subtraction (m c lies in [1/2, 2]); |r| < 2^-7. Then
** y = (e + L) + p(r), L = lod_log2_l[row] = -log2(c) rounded to nearest
** (c = 1 and L = 0 for the two rows next to m = 1), p the series of
** log2(1 + r) to r^6 by Horner. Error: the truncated series is within
** |r|^6 / 7 < 2^-44.8 of log2(1 + r) relatively, and the roundings of
** Horner's scheme and of the coefficients add less than 2^-50: p is
** within 2^-44.7 of log2(1 + r) relatively. With e = 0 on the rows of
** c = 1, y = p and that is the bound; on the other rows |log2 x| > 2^-7.5
** and the error is at most 2^-54 (L) + 2^-51.2 (p, |p| < 2^-6.4) +
** 2^-53.7 (the last addition), below 2^-43 |log2 x|; with e != 0,
** |log2 x| > max(0.41, |e| - 0.59) and the roundings of e + L and of the
** sum add at most 2^-52 (|e| + 0.6), so the error is below 2^-48 |log2 x|.
** So |y - log2 x| < 2^-43 |log2 x| <= 2^10 ulps of y, and glibc's log2 is
** within 1 ulp of log2 x (<= 2 ulps of y).
** Where no midpoint lies within 2^12 ulps of y, none lies between y,
** log2 x and glibc's result, which therefore round to the same float. The
** midpoints of y's binade are where the low 29 bits of y (those the
** conversion to float drops) are 2^28, so the distance in ulps is
** |low29 - 2^28|; those of the neighbouring binades lie at least 2^26 ulps
** away, and y = 0 (x = 1, where glibc's log2 is 0 too) is exact.
** (Over every positive finite float, with glibc 2.36: y is within 211
** ulps of log2 x, 33794 inputs go to log2, and the float of y would have
** been glibc's float for every one of them too.) */
#define LOD_LOG2_FAST 1
#define LOD_LOG2_NEAR ((int64_t)1 << 12)    /* ulps of y around a midpoint that go to log2 */

/* the approximation above, for a positive finite double x with at most
** 24 significant bits */
static inline double lod_log2_approx(double x)
{
    LodBits b = { x }, m;
    const uint64_t fold = (b.u >> 51) & 1;     /* m >= 1.5: m / 2, e + 1 */
    const int64_t e = (int64_t)(b.u >> 52) + (int64_t)fold - 1023;
    m.u = (b.u & (((uint64_t)1 << 52) - 1)) | ((1023 - fold) << 52);
    const int row = (int)((b.u >> 45) & 127);
    const double r = m.d * lod_log2_c[row] - 1;
    const double p = r * (LOD_LOG2_A1 + r * (LOD_LOG2_A2 + r * (LOD_LOG2_A3 + r * (LOD_LOG2_A4
                   + r * (LOD_LOG2_A5 + r * LOD_LOG2_A6)))));
    return ((double)e + lod_log2_l[row]) + p;
}

/* whether a float midpoint lies within LOD_LOG2_NEAR ulps of y */
static inline int lod_log2_near_mid(double y)
{
    LodBits b = { y };
    const uint64_t low = b.u & ((((uint64_t)1) << 29) - 1);
    return low - (((uint64_t)1 << 28) - (uint64_t)LOD_LOG2_NEAR) <= 2 * (uint64_t)LOD_LOG2_NEAR;
}

static inline LODV lod_log2(TEXC rho)
{
    if (!(rho > 0))
        return (NUM)-1e30;
    if (rho <= NUM_MAX) {
        const double y = lod_log2_approx((double)rho);
        if (!lod_log2_near_mid(y))
            return (NUM)y;
    }
    return (NUM)log2((double)rho);
}
#else
#define LOD_LOG2_FAST 0
/* The double build's lambda, log2 x of x = rho (positive, normal and
** finite; elsewhere the C library's log2), within 0.51 ulp: the float
** build's rows (x = 2^e m, |m c - 1| < 2^-7) with m c as the double mc
** and its exact error mc_lo (a fused multiply-add), r = mc - 1 exact (mc
** in [1/2, 2]); log2(1 + r + mc_lo) as r A1 (its double and the product's
** exact error, and r times A1's tail), mc_lo A1 (1 - r) and r^2 (A2 + ...
** + r^6 A8); -log2(c) as its double L and tail (tables_lod.h). (e + L) +
** r A1 are two exact sums (their errors join the tail), so one rounding
** at y's scale remains: the tail's terms are below 2^-14, their roundings
** and mc_lo's second-order term below 2^-66, the truncated series below
** 2^-65 (|r|^9 / (9 ln 2)). tests/test_lod_log2.py measures at most 0.509
** ulp against log2 to 40 digits. Every lane of lod_choose4_d does these
** operations in this order, so the vector code gives the same bits. */
#include "tables_lod.h"
#define LOD_LOG2_A7 0x1.a61762a7aded9p-3
#define LOD_LOG2_A8 (-0x1.71547652b82fep-3)
static inline double lod_log2_dd(double x)
{
    LodBits b = { x }, m;
    const uint64_t fold = (b.u >> 51) & 1;     /* m >= 1.5: m / 2, e + 1 */
    const double e = (double)((int64_t)(b.u >> 52) + (int64_t)fold - 1023);
    m.u = (b.u & (((uint64_t)1 << 52) - 1)) | ((1023 - fold) << 52);
    const int row = (int)((b.u >> 45) & 127);
    /* m c = mc + mc_lo exactly; r = mc - 1 is exact (mc in [1/2, 2]) */
    const double mc = m.d * lod_log2_c[row], mc_lo = fma(m.d, lod_log2_c[row], -mc), r = mc - 1.0;
    const double ph = r * LOD_LOG2_A1, pl = fma(r, LOD_LOG2_A1, -ph);
    const double q = (r * r) * (LOD_LOG2_A2 + r * (LOD_LOG2_A3 + r * (LOD_LOG2_A4 + r * (LOD_LOG2_A5
                   + r * (LOD_LOG2_A6 + r * (LOD_LOG2_A7 + r * LOD_LOG2_A8))))));
    /* s1 = e + L (|e| >= 1 > |L|, or e = 0), s2 = s1 + ph, with errors */
    const double L = lod_log2_l[row];
    const double s1 = e + L, err1 = L - (s1 - e);
    const double s2 = s1 + ph, v = s2 - s1, err2 = (s1 - (s2 - v)) + (ph - v);
    return s2 + (((err1 + err2) + (pl + lod_log2_l_lo[row])) + ((r * LOD_LOG2_A1_LO + mc_lo * (LOD_LOG2_A1 - r * LOD_LOG2_A1)) + q));
}
static inline LODV lod_log2(TEXC rho)
{
    if (!(rho > 0))
        return (NUM)-1e30;
    return rho >= 0x1p-1022 && rho <= 0x1.fffffffffffffp1023 ? lod_log2_dd(rho) : log2(rho);
}
#endif
static inline LODV lod_from_ratio(int n, int d) { return (NUM)n / (NUM)d; }
static inline LODV lod_from_double(double v) { return (NUM)v; }
static inline int64_t lod_ifloor(LODV l) { return dbl_to_i64(floor((double)l), -((int64_t)1 << 40), (int64_t)1 << 40); }
static inline FRAGV lod_frac(LODV l) { return l - NUM_FLOOR(l); }
#endif
/* }==================================================================== */

/* {==================================================================== */
/* Batches of vertices (vertex_batch.c, light.c): structure-of-arrays forms
** of num_dot, with exactly its arithmetic per lane. Loops run over `cnt`
** lanes, a multiple of NUM_LANES, in groups of NUM_LANES, so the compiler
** can vectorize them under its cheapest cost model (-O2). The fixed build
** skips a term whose coefficient is zero: its product is exactly 0 in the
** int64 sum, so the sum is the same. The float builds keep every term
** (0 * inf is NaN, and the vector units do them anyway). */

#define NUM_BATCH 64   /* the most lanes a batch has */
#define NUM_LANES 8
#define NUM_FOR_LANES(i, cnt) \
    for (int g_ = 0; g_ < (cnt); g_ += NUM_LANES) \
        for (int i = g_; i < g_ + NUM_LANES; i++)

/* num_from_double((double)f), the conversion of a FLOAT array component,
** with the fixed build's floor done inline: x = v + 1/2 is formed as
** dbl_to_i64 forms it, and for |x| < 2^32 floor(x) is the truncation less
** one when that lies above x. The same value, without a call per component. */
static inline NUM num_from_float(float f)
{
#if NUM_IS_FIXED
    double v = (double)f * 65536.0;
    if (!(v == v))
        return 0;
    if (v <= (double)INT32_MIN)
        return NUM_MIN;
    if (v >= (double)INT32_MAX)
        return NUM_MAX;
    double x = v + 0.5;
    int64_t t = (int64_t)x;
    return (NUM)(t - ((double)t > x));
#else
    return num_from_double((double)f);
#endif
}

#if NUM_IS_FIXED
/* one instance per pattern of nonzero coefficients (`mask`, constant at
** each call) and per w (`w_one`: every lane's w is NUM_ONE, so the last
** product is the constant m3 * NUM_ONE): the sum stays in a register, the
** terms are added in num_dot's order */
static inline void num_dot4_lanes_mask(NUM m0, NUM m1, NUM m2, NUM m3, const NUM *x, const NUM *y, const NUM *z,
                                       const NUM *w, NUM *restrict out, int cnt, const int mask, const int w_one)
{
    const int64_t c3 = (int64_t)m3 * NUM_ONE;
    NUM_FOR_LANES(i, cnt) {
        NumAcc acc = { 0 };
        int64_t p;
        if (mask & 1) {
            p = (int64_t)m0 * x[i];
            NUM_ACC_ADD(acc, p);
        }
        if (mask & 2) {
            p = (int64_t)m1 * y[i];
            NUM_ACC_ADD(acc, p);
        }
        if (mask & 4) {
            p = (int64_t)m2 * z[i];
            NUM_ACC_ADD(acc, p);
        }
        if (mask & 8) {
            p = w_one ? c3 : (int64_t)m3 * w[i];
            NUM_ACC_ADD(acc, p);
        }
        out[i] = num_acc_round(acc);
    }
}

#define NUM_DOT4_CASE(k) \
    case k: \
        if (w_one) \
            num_dot4_lanes_mask(m0, m1, m2, m3, x, y, z, w, out, cnt, k, 1); \
        else \
            num_dot4_lanes_mask(m0, m1, m2, m3, x, y, z, w, out, cnt, k, 0); \
        break;
#endif

/* out[i] = m0 x[i] + m1 y[i] + m2 z[i] + m3 w[i], as num_dot(m, stride,
** (x, y, z, w), 1, 4) rounds it; cnt <= NUM_BATCH; out must not alias the
** inputs. `w_one`: the caller knows every lane's w is NUM_ONE */
static inline void num_dot4_lanes(NUM m0, NUM m1, NUM m2, NUM m3, const NUM *x, const NUM *y, const NUM *z,
                                  const NUM *w, NUM *restrict out, int cnt, int w_one)
{
#if NUM_IS_FIXED
    switch ((m0 != 0) | (m1 != 0) << 1 | (m2 != 0) << 2 | (m3 != 0) << 3) {
    NUM_DOT4_CASE(0) NUM_DOT4_CASE(1) NUM_DOT4_CASE(2) NUM_DOT4_CASE(3)
    NUM_DOT4_CASE(4) NUM_DOT4_CASE(5) NUM_DOT4_CASE(6) NUM_DOT4_CASE(7)
    NUM_DOT4_CASE(8) NUM_DOT4_CASE(9) NUM_DOT4_CASE(10) NUM_DOT4_CASE(11)
    NUM_DOT4_CASE(12) NUM_DOT4_CASE(13) NUM_DOT4_CASE(14) NUM_DOT4_CASE(15)
    default: break;
    }
#else
    (void)w_one;
    NUM_FOR_LANES(i, cnt) {
        NUM acc = 0;
        acc += m0 * x[i];
        acc += m1 * y[i];
        acc += m2 * z[i];
        acc += m3 * w[i];
        out[i] = acc;
    }
#endif
}

#if NUM_IS_FIXED
/* num_dot3_lanes for one pattern of nonzero coefficients */
static inline void num_dot3_lanes_mask(NUM m0, NUM m1, NUM m2, const NUM *x, const NUM *y, const NUM *z,
                                       NUM *restrict out, int cnt, const int mask)
{
    NUM_FOR_LANES(i, cnt) {
        NumAcc acc = { 0 };
        int64_t p;
        if (mask & 1) {
            p = (int64_t)m0 * x[i];
            NUM_ACC_ADD(acc, p);
        }
        if (mask & 2) {
            p = (int64_t)m1 * y[i];
            NUM_ACC_ADD(acc, p);
        }
        if (mask & 4) {
            p = (int64_t)m2 * z[i];
            NUM_ACC_ADD(acc, p);
        }
        out[i] = num_acc_round(acc);
    }
}

#define NUM_DOT3_CASE(k) \
    case k: \
        num_dot3_lanes_mask(m0, m1, m2, x, y, z, out, cnt, k); \
        break;
#endif

/* out[i] = m0 x[i] + m1 y[i] + m2 z[i], as num_dot(m, 1, (x, y, z), 1, 3) */
static inline void num_dot3_lanes(NUM m0, NUM m1, NUM m2, const NUM *x, const NUM *y, const NUM *z,
                                  NUM *restrict out, int cnt)
{
#if NUM_IS_FIXED
    switch ((m0 != 0) | (m1 != 0) << 1 | (m2 != 0) << 2) {
    NUM_DOT3_CASE(0) NUM_DOT3_CASE(1) NUM_DOT3_CASE(2) NUM_DOT3_CASE(3)
    NUM_DOT3_CASE(4) NUM_DOT3_CASE(5) NUM_DOT3_CASE(6) NUM_DOT3_CASE(7)
    default: break;
    }
#else
    NUM_FOR_LANES(i, cnt) {
        NUM acc = 0;
        acc += m0 * x[i];
        acc += m1 * y[i];
        acc += m2 * z[i];
        out[i] = acc;
    }
#endif
}
/* }==================================================================== */

#endif
