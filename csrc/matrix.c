/*
** matrix.c -- MatrixMode, the stacks and every matrix command (ES 1.1 §2.10).
** Owns: each stack entry's two forms, the double matrix the application built
**       (returned by queries) and the NUM matrix built by this build's own
**       arithmetic (what vertices are transformed with), so that the fixed
**       build accumulates the rounding a 16.16 device would.
** Never does: per-vertex work (vertex.c), derived composites (draw.c).
*/
#include <string.h>
#include "matrix.h"

static const double identity_d[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };

static void matrix_set_identity(Matrix *m)
{
    memcpy(m->d, identity_d, sizeof m->d);
    for (int i = 0; i < 16; i++)
        m->n[i] = (i % 5 == 0) ? NUM_ONE : NUM_ZERO;
    m->kind = MAT_IDENTITY;
}

void matrix_stack_init(MatrixStack *s, int capacity)
{
    s->capacity = capacity;
    s->depth = 1;
    s->top = &s->entries[0];
    matrix_set_identity(s->top);
}

int matrix_kind(const NUM *m)
{
    if (m[3] != NUM_ZERO || m[7] != NUM_ZERO || m[11] != NUM_ZERO || m[15] != NUM_ONE)
        return MAT_GENERAL;
    for (int i = 0; i < 15; i++) /* the translation column counts too */
        if (m[i] != ((i % 5 == 0) ? NUM_ONE : NUM_ZERO))
            return MAT_AFFINE;
    return MAT_IDENTITY;
}

void matrix_mul_num(NUM *r, const NUM *a, const NUM *b)
{
    NUM t[16];
    for (int c = 0; c < 4; c++)
        for (int row = 0; row < 4; row++)
            t[c * 4 + row] = num_dot(a + row, 4, b + c * 4, 1, 4);
    memcpy(r, t, sizeof t);
}

static void matrix_mul_d(double *r, const double *a, const double *b)
{
    double t[16];
    for (int c = 0; c < 4; c++)
        for (int row = 0; row < 4; row++) {
            double acc = 0;
            for (int k = 0; k < 4; k++)
                acc += a[k * 4 + row] * b[c * 4 + k];
            t[c * 4 + row] = acc;
        }
    memcpy(r, t, sizeof t);
}

void matrix_xform4(const NUM *m, int kind, const NUM *v, NUM *out)
{
    if (kind == MAT_IDENTITY) {
        memmove(out, v, 4 * sizeof(NUM));
        return;
    }
    NUM r[4];
    for (int row = 0; row < 3; row++)
        r[row] = num_dot(m + row, 4, v, 1, 4);
    r[3] = kind == MAT_AFFINE ? v[3] : num_dot(m + 3, 4, v, 1, 4);
    memcpy(out, r, sizeof r);
}

int matrix_invert_d(double *inv, const double *m)
{
    /* Gauss-Jordan with partial pivoting on [m | I] */
    double a[4][8];
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++) {
            a[r][c] = m[c * 4 + r];
            a[r][c + 4] = r == c;
        }
    for (int c = 0; c < 4; c++) {
        int p = c;
        for (int r = c + 1; r < 4; r++)
            if (fabs(a[r][c]) > fabs(a[p][c]))
                p = r;
        if (a[p][c] == 0.0)
            return 0;
        if (p != c)
            for (int k = 0; k < 8; k++) {
                double t = a[c][k];
                a[c][k] = a[p][k];
                a[p][k] = t;
            }
        double s = 1.0 / a[c][c];
        for (int k = 0; k < 8; k++)
            a[c][k] *= s;
        for (int r = 0; r < 4; r++)
            if (r != c && a[r][c] != 0.0) {
                double f = a[r][c];
                for (int k = 0; k < 8; k++)
                    a[r][k] -= f * a[c][k];
            }
    }
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++)
            inv[c * 4 + r] = a[r][c + 4];
    return 1;
}

/* {====================================================================
** commands */

static void touched(GlesContext *ctx)
{
    Matrix *m = ctx->current_stack->top;
    m->kind = matrix_kind(m->n);
    ctx->dirty |= DIRTY_MATRIX;
}

void gles_MatrixMode(GlesContext *ctx, unsigned int mode)
{
    switch (mode) {
    case GL_MODELVIEW: ctx->current_stack = &ctx->modelview; break;
    case GL_PROJECTION: ctx->current_stack = &ctx->projection; break;
    case GL_TEXTURE: ctx->current_stack = &ctx->texture[ctx->active_texture - GL_TEXTURE0]; break;
    case GL_MATRIX_PALETTE_OES: ctx->current_stack = &ctx->palette_stack; break;
    default:
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->matrix_mode = mode;
}

void gles_LoadIdentity(GlesContext *ctx)
{
    matrix_set_identity(ctx->current_stack->top);
    touched(ctx);
}

void gles_LoadMatrix(GlesContext *ctx, const double *m)
{
    Matrix *t = ctx->current_stack->top;
    for (int i = 0; i < 16; i++) {
        t->d[i] = m[i];
        t->n[i] = num_from_double(m[i]);
    }
    touched(ctx);
}

/* top = top * (m in both forms) */
static void mult_both(GlesContext *ctx, const double *md, const NUM *mn)
{
    Matrix *t = ctx->current_stack->top;
    matrix_mul_d(t->d, t->d, md);
    matrix_mul_num(t->n, t->n, mn);
    touched(ctx);
}

void gles_MultMatrix(GlesContext *ctx, const double *m)
{
    NUM mn[16];
    for (int i = 0; i < 16; i++)
        mn[i] = num_from_double(m[i]);
    mult_both(ctx, m, mn);
}

void gles_PushMatrix(GlesContext *ctx)
{
    MatrixStack *s = ctx->current_stack;
    if (s->depth >= s->capacity) {
        ctx_error(ctx, GL_STACK_OVERFLOW);
        return;
    }
    s->entries[s->depth] = *s->top;
    s->top = &s->entries[s->depth];
    s->depth++;
}

void gles_PopMatrix(GlesContext *ctx)
{
    MatrixStack *s = ctx->current_stack;
    if (s->depth <= 1) {
        ctx_error(ctx, GL_STACK_UNDERFLOW);
        return;
    }
    s->depth--;
    s->top = &s->entries[s->depth - 1];
    ctx->dirty |= DIRTY_MATRIX;
}

/* multiply by the identity with x, y, z placed at elements i, j, k (the
** translation column or the diagonal) */
static void mult_placed(GlesContext *ctx, int i, int j, int k, double x, double y, double z)
{
    double md[16];
    NUM mn[16];
    memcpy(md, identity_d, sizeof md);
    for (int e = 0; e < 16; e++)
        mn[e] = (e % 5 == 0) ? NUM_ONE : NUM_ZERO;
    md[i] = x; md[j] = y; md[k] = z;
    mn[i] = num_from_double(x);
    mn[j] = num_from_double(y);
    mn[k] = num_from_double(z);
    mult_both(ctx, md, mn);
}

void gles_Translate(GlesContext *ctx, double x, double y, double z) { mult_placed(ctx, 12, 13, 14, x, y, z); }
void gles_Scale(GlesContext *ctx, double x, double y, double z) { mult_placed(ctx, 0, 5, 10, x, y, z); }

/* the rotation matrix of §2.10.2 for unit axis (x,y,z), sine s, cosine c */
#define ROTATION_BODY(T, MUL, ADD, SUB, ONE)                                  \
    do {                                                                      \
        T omc = SUB(ONE, c);                                                  \
        T xx = MUL(x, x), yy = MUL(y, y), zz = MUL(z, z);                     \
        T xy = MUL(x, y), yz = MUL(y, z), zx = MUL(z, x);                     \
        T xs = MUL(x, s), ys = MUL(y, s), zs = MUL(z, s);                     \
        r[0] = ADD(MUL(xx, omc), c);  r[4] = SUB(MUL(xy, omc), zs);           \
        r[8] = ADD(MUL(zx, omc), ys);                                         \
        r[1] = ADD(MUL(xy, omc), zs); r[5] = ADD(MUL(yy, omc), c);            \
        r[9] = SUB(MUL(yz, omc), xs);                                         \
        r[2] = SUB(MUL(zx, omc), ys); r[6] = ADD(MUL(yz, omc), xs);           \
        r[10] = ADD(MUL(zz, omc), c);                                         \
        r[3] = r[7] = r[11] = r[12] = r[13] = r[14] = 0; r[15] = ONE;         \
    } while (0)

static double d_mul(double a, double b) { return a * b; }
static double d_add(double a, double b) { return a + b; }
static double d_sub(double a, double b) { return a - b; }

static void rotation_d(double *r, double angle, double x, double y, double z)
{
    double len = sqrt(x * x + y * y + z * z);
    x /= len; y /= len; z /= len;
    double a = fmod(angle, 360.0);
    const double pi = 3.14159265358979323846;
    double s = sin(a * pi / 180.0), c = cos(a * pi / 180.0);
    if (fmod(a, 90.0) == 0.0) { /* keep quarter turns exact */
        int q = ((int)(a / 90.0) % 4 + 4) % 4;
        static const double qs[4] = { 0, 1, 0, -1 }, qc[4] = { 1, 0, -1, 0 };
        s = qs[q]; c = qc[q];
    }
    ROTATION_BODY(double, d_mul, d_add, d_sub, 1.0);
}

static void rotation_n(NUM *r, double angle, double xd, double yd, double zd)
{
    NUM axis[3] = { num_from_double(xd), num_from_double(yd), num_from_double(zd) };
    if (!num_normalize3(axis)) {
        /* an axis too short for this build: normalise the exact one instead */
        double len = sqrt(xd * xd + yd * yd + zd * zd);
        axis[0] = num_from_double(xd / len);
        axis[1] = num_from_double(yd / len);
        axis[2] = num_from_double(zd / len);
    }
    NUM x = axis[0], y = axis[1], z = axis[2];
    NUM s, c;
    num_sincos_deg(num_from_double(angle), &s, &c);
    ROTATION_BODY(NUM, num_mul, num_add, num_sub, NUM_ONE);
}

void gles_Rotate(GlesContext *ctx, double angle, double x, double y, double z)
{
    if (x == 0.0 && y == 0.0 && z == 0.0) {
        /* undefined axis: leave the matrix alone rather than fill it with NaN */
        return;
    }
    double md[16];
    NUM mn[16];
    rotation_d(md, angle, x, y, z);
    rotation_n(mn, angle, x, y, z);
    mult_both(ctx, md, mn);
}

/* glFrustum and glOrtho build their matrix from quotients; the NUM form is
** computed with this build's division so the fixed build rounds as a device
** would. */
void gles_Frustum(GlesContext *ctx, double l, double r, double b, double t, double n, double f)
{
    if (n <= 0 || f <= 0 || l == r || b == t || n == f) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    double md[16] = { 0 };
    md[0] = 2 * n / (r - l);
    md[5] = 2 * n / (t - b);
    md[8] = (r + l) / (r - l);
    md[9] = (t + b) / (t - b);
    md[10] = -(f + n) / (f - n);
    md[11] = -1;
    md[14] = -2 * f * n / (f - n);
    NUM L = num_from_double(l), R = num_from_double(r), B = num_from_double(b), T = num_from_double(t);
    NUM N = num_from_double(n), F = num_from_double(f);
    /* sums and differences exact (NUMW), each element one rounded ratio:
    ** a 16.16 device with 64-bit intermediates loses nothing more */
    NUMW rl = numw(R) - numw(L), tb = numw(T) - numw(B), fn = numw(F) - numw(N);
    NUM mn[16] = { 0 };
    if (rl == 0 || tb == 0 || fn == 0) {
        /* distinct doubles that round to one value: fall back to rounding
        ** the double matrix rather than dividing by zero */
        for (int i = 0; i < 16; i++)
            mn[i] = num_from_double(md[i]);
    } else {
        mn[0] = num_div_w(2 * numw(N), rl);
        mn[5] = num_div_w(2 * numw(N), tb);
        mn[8] = num_div_w(numw(R) + numw(L), rl);
        mn[9] = num_div_w(numw(T) + numw(B), tb);
        mn[10] = num_neg(num_div_w(numw(F) + numw(N), fn));
        mn[11] = num_neg(NUM_ONE);
        mn[14] = num_neg(num_muldiv_w(2, F, N, fn));
    }
    mult_both(ctx, md, mn);
}

void gles_Ortho(GlesContext *ctx, double l, double r, double b, double t, double n, double f)
{
    if (l == r || b == t || n == f) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    double md[16] = { 0 };
    md[0] = 2 / (r - l);
    md[5] = 2 / (t - b);
    md[10] = -2 / (f - n);
    md[12] = -(r + l) / (r - l);
    md[13] = -(t + b) / (t - b);
    md[14] = -(f + n) / (f - n);
    md[15] = 1;
    NUM L = num_from_double(l), R = num_from_double(r), B = num_from_double(b), T = num_from_double(t);
    NUM N = num_from_double(n), F = num_from_double(f);
    NUMW rl = numw(R) - numw(L), tb = numw(T) - numw(B), fn = numw(F) - numw(N);
    NUM mn[16] = { 0 };
    if (rl == 0 || tb == 0 || fn == 0) {
        for (int i = 0; i < 16; i++)
            mn[i] = num_from_double(md[i]);
    } else {
        NUMW two = numw(num_from_int(2));
        mn[0] = num_div_w(two, rl);
        mn[5] = num_div_w(two, tb);
        mn[10] = num_neg(num_div_w(two, fn));
        mn[12] = num_neg(num_div_w(numw(R) + numw(L), rl));
        mn[13] = num_neg(num_div_w(numw(T) + numw(B), tb));
        mn[14] = num_neg(num_div_w(numw(F) + numw(N), fn));
        mn[15] = NUM_ONE;
    }
    mult_both(ctx, md, mn);
}

/* §2.11.2: the plane is transformed by the inverse of the modelview current
** at the call, p_eye = p * M^-1; derived in double from the exact matrix. */
void gles_ClipPlane(GlesContext *ctx, unsigned int plane, const double *eq)
{
    if (plane < GL_CLIP_PLANE0 || plane >= GL_CLIP_PLANE0 + GLES_MAX_CLIP_PLANES) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    unsigned int i = plane - GL_CLIP_PLANE0;
    double inv[16];
    double pe[4] = { 0, 0, 0, 0 };
    if (matrix_invert_d(inv, ctx->modelview.top->d)) {
        for (int c = 0; c < 4; c++)
            for (int k = 0; k < 4; k++)
                pe[c] += eq[k] * inv[c * 4 + k];
    }
    for (int c = 0; c < 4; c++) {
        ctx->clip_plane[i][c] = pe[c];
        ctx->clip_plane_n[i][c] = num_from_double(pe[c]);
    }
    ctx->dirty |= DIRTY_CLIP;
}

void gles_GetClipPlane(GlesContext *ctx, unsigned int plane, double *eq)
{
    if (plane < GL_CLIP_PLANE0 || plane >= GL_CLIP_PLANE0 + GLES_MAX_CLIP_PLANES) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    for (int c = 0; c < 4; c++)
        eq[c] = ctx->clip_plane[plane - GL_CLIP_PLANE0][c];
}

/* {====================================================================
** OES_matrix_palette */

void matrix_palette_init(GlesContext *ctx)
{
    for (int i = 0; i < GLES_MAX_PALETTE_MATRICES; i++)
        matrix_set_identity(&ctx->palette[i]);
    ctx->palette_stack.capacity = 1;
    ctx->palette_stack.depth = 1;
    ctx->palette_stack.top = &ctx->palette[0];
    ctx->current_palette = 0;
}

void gles_CurrentPaletteMatrixOES(GlesContext *ctx, unsigned int index)
{
    if (index >= GLES_MAX_PALETTE_MATRICES) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    ctx->current_palette = index;
    ctx->palette_stack.top = &ctx->palette[index];
}

void gles_LoadPaletteFromModelViewMatrixOES(GlesContext *ctx)
{
    ctx->palette[ctx->current_palette] = *ctx->modelview.top;
    ctx->dirty |= DIRTY_MATRIX;
}
