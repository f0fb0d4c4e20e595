/*
** matrix.h -- matrix stacks and 4x4 arithmetic in NUM and in double.
*/
#ifndef GLES_MATRIX_H
#define GLES_MATRIX_H

#include "state.h"

void matrix_stack_init(MatrixStack *s, int capacity);
void matrix_palette_init(GlesContext *ctx);
/* r = a * b for NUM matrices (column-major), rounding each element once */
void matrix_mul_num(NUM *r, const NUM *a, const NUM *b);
/* classify a NUM matrix (identity, affine, general) */
int matrix_kind(const NUM *m);
/* out = m * v for a 4-vector */
void matrix_xform4(const NUM *m, int kind, const NUM *v, NUM *out);
/* inverse of a double matrix; returns 0 when singular */
int matrix_invert_d(double *inv, const double *m);

#endif
