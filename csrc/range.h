/*
** range.h -- the per-draw overflow rule for 16.16 pipelines (McReynolds and
** Blythe, "Advanced Graphics Programming Using OpenGL", 8.3.2).
*/
#ifndef GLES_RANGE_H
#define GLES_RANGE_H

#include "state.h"

/* half of the 16.16 range [-32768, 32768): the rule's X / 2 */
#define RANGE_HALF_LIMIT 16384.0
/* |x| at and above this does not fit 16.16 */
#define RANGE_VALUE_LIMIT 32768.0

/* GLES_OK, or GLES_RANGE when c*s + t >= X/2 for the vertices lo..hi of the
** vertex array and the current P*MV, or when an enabled FLOAT array holds a
** drawn value |x| >= 32768; the numbers are kept for gles_range_last.
** Counts the draw. */
int range_check_draw(GlesContext *ctx, int64_t lo, int64_t hi);
/* the largest |component| of vertices lo..hi of array `a` (elements at
** base), infinity when one is NaN or infinite; a FLOAT array through the
** AVX2 scan where `simd` (the CPU must have AVX2) */
double range_array_max(const ArrayState *a, const uint8_t *base, int64_t lo, int64_t hi, int simd);

#endif
