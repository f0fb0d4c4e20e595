/*
** range.c -- the per-draw overflow rule of a 16.16 pipeline.
** With s the largest |element| of the upper 3x3 of P*MV, t the largest
** |element| of its 4th column and c the largest |component| of the vertices
** a draw reads, an application stays clear of overflow while
** c*s + t < X/2 for the range [-X, X] (McReynolds and Blythe, 8.3.2).
** Consumes: the double matrices (the application's, not the build's), the
**       vertex array.  Never does: per-value checks (profile.py does those).
** Cost: s and t from one 4x4 double product per draw (one per palette
**       matrix with OES_matrix_palette); c from a scan of the drawn vertices
**       of a client array (client memory can change at any time), and from a
**       bound cached per buffer contents for a buffer object, rescanned over
**       the drawn vertices only when the cached bound breaks the rule.
*/
#include <math.h>
#include <string.h>
#include "range.h"
#include "array.h"
#include "vertex_avx2.h"

/* largest |component| of vertices lo..hi; NaN and infinities give +inf.
** `simd`: a FLOAT array goes through the AVX2 scan (vertex_avx2.h) */
double range_array_max(const ArrayState *a, const uint8_t *base, int64_t lo, int64_t hi, int simd)
{
#if RANGE_AVX2
    if (simd && a->type == GL_FLOAT && a->size >= 1 && a->size <= 4)
        return vx_float_abs_max_avx2(base, a->step, a->size, lo, hi);
#endif
    (void)simd;
    double c = 0.0;
    for (int64_t i = lo; i <= hi; i++) {
        const uint8_t *p = base + i * a->step;
        for (int k = 0; k < a->size; k++) {
            double v;
            switch (a->type) {
            case GL_BYTE: { int8_t x; memcpy(&x, p + k, 1); v = x; break; }
            case GL_SHORT: { int16_t x; memcpy(&x, p + 2 * k, 2); v = x; break; }
            case GL_FIXED: { int32_t x; memcpy(&x, p + 4 * k, 4); v = x / 65536.0; break; }
            default: { float x; memcpy(&x, p + 4 * k, 4); v = x; break; }
            }
            v = fabs(v);
            if (!(v <= c))            /* also catches NaN */
                c = isnan(v) ? INFINITY : v;
        }
    }
    return c;
}

/* s and t of P*M, maximised into *s and *t */
static void range_matrix_st(const double *p, const double *m, double *s, double *t)
{
    for (int col = 0; col < 4; col++)
        for (int row = 0; row < 4; row++) {
            if (col < 3 && row == 3)
                continue;             /* the w row is outside both parts */
            double acc = 0.0;
            for (int k = 0; k < 4; k++)
                acc += p[k * 4 + row] * m[col * 4 + k];
            acc = isnan(acc) ? INFINITY : fabs(acc);
            double *dst = col < 3 ? s : t;
            if (acc > *dst)
                *dst = acc;
        }
}

static int64_t range_vertex_count(const ArrayState *a)
{
    int64_t bytes = a->buffer ? a->buffer->size - (int64_t)(uintptr_t)a->ptr : a->nbytes;
    if (bytes < a->elem_bytes || a->step <= 0)
        return 0;
    return (bytes - a->elem_bytes) / a->step + 1;
}

/* largest |component| of array `index` over vertices lo..hi: a buffer
** object's cached bound of its whole contents when `fine` accepts it (the
** drawn vertices are within it), else a scan of the drawn range */
static double range_bound(GlesContext *ctx, int index, int64_t lo, int64_t hi, int (*fine)(double, void *),
                          void *arg)
{
    ArrayState *a = &ctx->arrays[index];
    const uint8_t *base = array_base(a);
    const int simd = ctx_simd(ctx) >= SIMD_AVX2;
    if (!a->buffer)
        return range_array_max(a, base, lo, hi, simd);
    if (!a->range_cached || a->range_serial != ctx->buffer_serial) {
        a->range_max = range_array_max(a, base, 0, range_vertex_count(a) - 1, simd);
        a->range_serial = ctx->buffer_serial;
        a->range_cached = 1;
    }
    return fine(a->range_max, arg) ? a->range_max : range_array_max(a, base, lo, hi, simd);
}

static int range_value_fine(double c, void *arg)
{
    (void)arg;
    return c < RANGE_VALUE_LIMIT;
}

static int range_vertex_fine(double c, void *arg)
{
    const double *st = arg;
    return c * st[0] + st[1] < RANGE_HALF_LIMIT && c < RANGE_VALUE_LIMIT;
}

_Static_assert(ARR_COUNT == GLES_RANGE_ARRAYS, "gles_range_last reports every array");

int range_check_draw(GlesContext *ctx, int64_t lo, int64_t hi)
{
    const double *proj = ctx->projection.top->d;
    double st[2] = { 0.0, 0.0 };
    if (ctx->matrix_palette)
        for (int k = 0; k < GLES_MAX_PALETTE_MATRICES; k++)
            range_matrix_st(proj, ctx->palette[k].d, &st[0], &st[1]);
    else
        range_matrix_st(proj, ctx->modelview.top->d, &st[0], &st[1]);

    ctx->range_draws++;
    int result = GLES_OK;
    double c = range_bound(ctx, ARR_VERTEX, lo, hi, range_vertex_fine, st);
    double lhs = c * st[0] + st[1];
    if (st[0] == 0.0 && isinf(c))
        lhs = INFINITY;               /* a non-finite vertex breaks any matrix */
    if (!(lhs < RANGE_HALF_LIMIT)) {
        ctx->range_violations++;
        result = GLES_RANGE;
    }
    /* per value: FLOAT arrays whose drawn values 16.16 cannot hold (the
    ** other types always fit) */
    ctx->range_arrays = 0;
    for (int i = 0; i < ARR_COUNT; i++) {
        const ArrayState *a = &ctx->arrays[i];
        if (!a->enabled || a->type != GL_FLOAT)
            continue;
        double m = i == ARR_VERTEX ? c : range_bound(ctx, i, lo, hi, range_value_fine, NULL);
        if (!(m < RANGE_VALUE_LIMIT)) {
            ctx->range_arrays |= 1u << i;
            ctx->range_array_max[i] = m;
            result = GLES_RANGE;
        }
    }
    if (result) {
        ctx->range_last[0] = c;
        ctx->range_last[1] = st[0];
        ctx->range_last[2] = st[1];
        ctx->range_last[3] = lhs;
    }
    return result;
}

void gles_range_set(GlesContext *ctx, int mode) { ctx->range_mode = mode; }

int gles_range_last(GlesContext *ctx, double out[4], double array_max[GLES_RANGE_ARRAYS])
{
    memcpy(out, ctx->range_last, 4 * sizeof(double));
    for (int i = 0; i < GLES_RANGE_ARRAYS; i++)
        array_max[i] = i < ARR_COUNT && (ctx->range_arrays >> i & 1u) ? ctx->range_array_max[i] : 0.0;
    return (int)ctx->range_arrays;
}

void gles_range_reset(GlesContext *ctx)
{
    ctx->range_draws = ctx->range_violations = 0;
}

void gles_range_counts(GlesContext *ctx, int64_t out[2])
{
    out[0] = ctx->range_draws;
    out[1] = ctx->range_violations;
}
