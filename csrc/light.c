/*
** light.c -- the lighting equation of ES 1.1 §2.12.1 and its state.
** Owns: Light, LightModel, Material and their queries; the derived normal
**       matrix; the per-vertex colour of a lit vertex (front and back).
** Consumes: eye-space position (vertex.c), the normal, the vertex colour
**       (COLOR_MATERIAL tracks AMBIENT_AND_DIFFUSE, the only mode in ES).
** Numbers: light positions and directions are transformed into eye space
**       with this build's modelview at the call, as a device would. The
**       normal matrix is the inverse transpose of the build's own modelview
**       3x3, inverted in double and rounded once (a 16.16 inverse of a
**       general 3x3 loses most of its bits to the determinant). Vectors are
**       normalised with num_normalize3, which divides by the largest
**       component first, so lights far away do not overflow the fixed build.
*/
#include <string.h>
#include "state.h"
#include "matrix.h"
#include "light.h"
#include "texgen.h"
#include "vertex_avx2.h"

static void set4(double *d, NUM *n, const double *v, int count)
{
    for (int i = 0; i < count; i++) {
        d[i] = v[i];
        n[i] = num_from_double(v[i]);
    }
}

void light_init(GlesContext *ctx)
{
    static const double black[4] = { 0, 0, 0, 1 }, white[4] = { 1, 1, 1, 1 };
    static const double pos[4] = { 0, 0, 1, 0 }, dir[3] = { 0, 0, -1 };
    static const double amb[4] = { 0.2, 0.2, 0.2, 1.0 }, dif[4] = { 0.8, 0.8, 0.8, 1.0 };
    for (int i = 0; i < GLES_MAX_LIGHTS; i++) {
        Light *l = &ctx->lights[i];
        set4(l->ambient, l->n_ambient, black, 4);
        set4(l->diffuse, l->n_diffuse, i == 0 ? white : black, 4);
        set4(l->specular, l->n_specular, i == 0 ? white : black, 4);
        set4(l->position, l->n_position, pos, 4);
        set4(l->spot_direction, l->n_spot_direction, dir, 3);
        l->spot_exponent = 0;
        l->n_spot_exponent = 0;
        l->spot_cutoff = 180;
        l->n_cos_cutoff = num_neg(NUM_ONE);
        static const double att[3] = { 1, 0, 0 };
        set4(l->attenuation, l->n_attenuation, att, 3);
    }
    Material *m = &ctx->material;
    set4(m->ambient, m->n_ambient, amb, 4);
    set4(m->diffuse, m->n_diffuse, dif, 4);
    set4(m->specular, m->n_specular, black, 4);
    set4(m->emission, m->n_emission, black, 4);
    m->shininess = 0;
    m->n_shininess = 0;
    set4(ctx->light_model_ambient, ctx->n_light_model_ambient, amb, 4);
}

/* {====================================================================
** commands */

void gles_Light(GlesContext *ctx, unsigned int light, unsigned int pname, const double *p, int vector)
{
    if (light < GL_LIGHT0 || light >= GL_LIGHT0 + GLES_MAX_LIGHTS) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    Light *l = &ctx->lights[light - GL_LIGHT0];
    const Matrix *mv = ctx->modelview.top;
    switch (pname) {
    case GL_AMBIENT: case GL_DIFFUSE: case GL_SPECULAR: case GL_POSITION: case GL_SPOT_DIRECTION:
        if (!vector) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
        break;
    default:
        break;
    }
    switch (pname) {
    case GL_AMBIENT: set4(l->ambient, l->n_ambient, p, 4); break;
    case GL_DIFFUSE: set4(l->diffuse, l->n_diffuse, p, 4); break;
    case GL_SPECULAR: set4(l->specular, l->n_specular, p, 4); break;
    case GL_POSITION: {
        /* §2.12.1: transformed by the modelview current at the call */
        NUM obj[4];
        for (int i = 0; i < 4; i++) {
            obj[i] = num_from_double(p[i]);
            l->position[i] = mv->d[i] * p[0] + mv->d[4 + i] * p[1] + mv->d[8 + i] * p[2] + mv->d[12 + i] * p[3];
        }
        matrix_xform4(mv->n, mv->kind, obj, l->n_position);
        break;
    }
    case GL_SPOT_DIRECTION: {
        NUM obj[4] = { num_from_double(p[0]), num_from_double(p[1]), num_from_double(p[2]), NUM_ZERO };
        NUM eye[4];
        for (int i = 0; i < 3; i++)
            l->spot_direction[i] = mv->d[i] * p[0] + mv->d[4 + i] * p[1] + mv->d[8 + i] * p[2];
        matrix_xform4(mv->n, mv->kind == MAT_IDENTITY ? MAT_IDENTITY : MAT_GENERAL, obj, eye);
        memcpy(l->n_spot_direction, eye, sizeof l->n_spot_direction);
        break;
    }
    case GL_SPOT_EXPONENT:
        if (!(p[0] >= 0 && p[0] <= 128)) {
            ctx_error(ctx, GL_INVALID_VALUE);
            return;
        }
        l->spot_exponent = p[0];
        l->n_spot_exponent = num_from_double(p[0]);
        break;
    case GL_SPOT_CUTOFF: {
        if (!((p[0] >= 0 && p[0] <= 90) || p[0] == 180)) {
            ctx_error(ctx, GL_INVALID_VALUE);
            return;
        }
        NUM s, c;
        num_sincos_deg(num_from_double(p[0]), &s, &c);
        l->spot_cutoff = p[0];
        l->n_cos_cutoff = c;
        break;
    }
    case GL_CONSTANT_ATTENUATION: case GL_LINEAR_ATTENUATION: case GL_QUADRATIC_ATTENUATION: {
        if (!(p[0] >= 0)) {
            ctx_error(ctx, GL_INVALID_VALUE);
            return;
        }
        int k = (int)(pname - GL_CONSTANT_ATTENUATION);
        l->attenuation[k] = p[0];
        l->n_attenuation[k] = num_from_double(p[0]);
        break;
    }
    default:
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->dirty |= DIRTY_LIGHT;
}

void gles_LightModel(GlesContext *ctx, unsigned int pname, const double *p, int vector)
{
    switch (pname) {
    case GL_LIGHT_MODEL_AMBIENT:
        if (!vector) {
            ctx_error(ctx, GL_INVALID_ENUM);
            return;
        }
        set4(ctx->light_model_ambient, ctx->n_light_model_ambient, p, 4);
        break;
    case GL_LIGHT_MODEL_TWO_SIDE:
        ctx->light_model_two_side = p[0] != 0.0;
        break;
    default:
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->dirty |= DIRTY_LIGHT;
}

void gles_Material(GlesContext *ctx, unsigned int face, unsigned int pname, const double *p, int vector)
{
    /* ES 1.1: materials are set for both faces at once */
    if (face != GL_FRONT_AND_BACK) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    Material *m = &ctx->material;
    if (pname != GL_SHININESS && !vector) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    switch (pname) {
    case GL_AMBIENT: set4(m->ambient, m->n_ambient, p, 4); break;
    case GL_DIFFUSE: set4(m->diffuse, m->n_diffuse, p, 4); break;
    case GL_SPECULAR: set4(m->specular, m->n_specular, p, 4); break;
    case GL_EMISSION: set4(m->emission, m->n_emission, p, 4); break;
    case GL_AMBIENT_AND_DIFFUSE:
        set4(m->ambient, m->n_ambient, p, 4);
        set4(m->diffuse, m->n_diffuse, p, 4);
        break;
    case GL_SHININESS:
        if (!(p[0] >= 0 && p[0] <= 128)) {
            ctx_error(ctx, GL_INVALID_VALUE);
            return;
        }
        m->shininess = p[0];
        m->n_shininess = num_from_double(p[0]);
        break;
    default:
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->dirty |= DIRTY_LIGHT;
}

static int copy_out(double *out, const double *v, int n)
{
    memcpy(out, v, (size_t)n * sizeof *v);
    return n;
}

int gles_GetLight(GlesContext *ctx, unsigned int light, unsigned int pname, double *out)
{
    if (light < GL_LIGHT0 || light >= GL_LIGHT0 + GLES_MAX_LIGHTS) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return 0;
    }
    const Light *l = &ctx->lights[light - GL_LIGHT0];
    switch (pname) {
    case GL_AMBIENT: return copy_out(out, l->ambient, 4);
    case GL_DIFFUSE: return copy_out(out, l->diffuse, 4);
    case GL_SPECULAR: return copy_out(out, l->specular, 4);
    case GL_POSITION: return copy_out(out, l->position, 4);
    case GL_SPOT_DIRECTION: return copy_out(out, l->spot_direction, 3);
    case GL_SPOT_EXPONENT: return copy_out(out, &l->spot_exponent, 1);
    case GL_SPOT_CUTOFF: return copy_out(out, &l->spot_cutoff, 1);
    case GL_CONSTANT_ATTENUATION: case GL_LINEAR_ATTENUATION: case GL_QUADRATIC_ATTENUATION:
        return copy_out(out, &l->attenuation[pname - GL_CONSTANT_ATTENUATION], 1);
    default:
        ctx_error(ctx, GL_INVALID_ENUM);
        return 0;
    }
}

int gles_GetMaterial(GlesContext *ctx, unsigned int face, unsigned int pname, double *out)
{
    if (face != GL_FRONT && face != GL_BACK) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return 0;
    }
    const Material *m = &ctx->material;
    switch (pname) {
    case GL_AMBIENT: return copy_out(out, m->ambient, 4);
    case GL_DIFFUSE: return copy_out(out, m->diffuse, 4);
    case GL_SPECULAR: return copy_out(out, m->specular, 4);
    case GL_EMISSION: return copy_out(out, m->emission, 4);
    case GL_SHININESS: return copy_out(out, &m->shininess, 1);
    default:
        ctx_error(ctx, GL_INVALID_ENUM);
        return 0;
    }
}

/* COLOR_MATERIAL: the current colour becomes the material's ambient and
** diffuse (at glColor and when the mode is enabled) */
void light_track_color(GlesContext *ctx)
{
    if (!ctx->color_material)
        return;
    Material *m = &ctx->material;
    set4(m->ambient, m->n_ambient, ctx->cur_color, 4);
    set4(m->diffuse, m->n_diffuse, ctx->cur_color, 4);
    ctx->dirty |= DIRTY_LIGHT;
}

/* {====================================================================
** derived state */

/* the normal matrix (inverse transpose of the 3x3 of `mn`, row-major) and
** the RESCALE_NORMAL factor */
static void normal_matrix_of(const NUM *mn, NUM nm[9], NUM *rescale)
{
    double m[16] = { 0 }, inv[16];
    for (int c = 0; c < 3; c++)
        for (int r = 0; r < 3; r++)
            m[c * 4 + r] = num_to_double(mn[c * 4 + r]);
    m[15] = 1;
    if (!matrix_invert_d(inv, m)) {
        memset(nm, 0, 9 * sizeof *nm);
        *rescale = NUM_ONE;
        return;
    }
    /* n_eye = n^T M^-1: n_eye[j] = sum_i n[i] inv[i][j]; row j of the
    ** normal matrix is column j of M^-1 */
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 3; i++)
            nm[j * 3 + i] = num_from_double(inv[j * 4 + i]);
    /* §2.11.3: f = 1 / |third row of M^-1| */
    double r = sqrt(inv[2] * inv[2] + inv[6] * inv[6] + inv[10] * inv[10]);
    *rescale = num_from_double(r > 0 ? 1.0 / r : 1.0);
}

/* The parts of light_side that do not depend on the vertex, computed once
** per state change with the same operations in the same order: the
** material products, and for a directional light its unit direction, spot
** factor and half vector (the viewer is at infinity in ES, so h is constant
** too). A directional light that can contribute nothing (zero direction,
** every vertex outside its cone) is left out. */
static void prepare_lights(GlesContext *ctx)
{
    const Material *m = &ctx->material;
    for (int k = 0; k < 3; k++)
        ctx->light_base[k] = num_add(m->n_emission[k], num_mul(m->n_ambient[k], ctx->n_light_model_ambient[k]));
    int cnt = 0;
    for (unsigned int bits = ctx->active_lights; bits; bits &= bits - 1) {
        const Light *l = &ctx->lights[__builtin_ctz(bits)];
        LightPrep *p = &ctx->light_prep[cnt];
        memset(p, 0, sizeof *p);
        p->l = l;
        for (int k = 0; k < 3; k++) {
            p->amb[k] = num_mul(m->n_ambient[k], l->n_ambient[k]);
            p->dif[k] = num_mul(m->n_diffuse[k], l->n_diffuse[k]);
            p->spec[k] = num_mul(m->n_specular[k], l->n_specular[k]);
        }
        if (l->n_position[3] != NUM_ZERO) {
            NUM pw = l->n_position[3];
            p->positional = 1;
            for (int k = 0; k < 3; k++)
                p->p[k] = pw == NUM_ONE ? l->n_position[k] : num_div(l->n_position[k], pw);
            const NUM *ka = l->n_attenuation;
            p->attenuate = ka[1] != NUM_ZERO || ka[2] != NUM_ZERO || ka[0] != NUM_ONE;
            p->spot = l->spot_cutoff != 180.0;
            p->specular = l->has_specular;
        } else {
            NUM vp[3] = { l->n_position[0], l->n_position[1], l->n_position[2] };
            if (!num_normalize3(vp))
                continue;
            NUM spot = NUM_ONE;
            if (l->spot_cutoff != 180.0) {
                NUM cosang = num_neg(num_dot(vp, 1, l->unit_spot_direction, 1, 3));
                if (cosang < l->n_cos_cutoff)
                    continue;
                spot = num_pow(cosang, l->n_spot_exponent);
            }
            p->scale = num_mul(NUM_ONE, spot);      /* att is one */
            memcpy(p->p, vp, sizeof vp);
            NUM h[3] = { vp[0], vp[1], num_add(vp[2], NUM_ONE) };
            p->specular = l->has_specular && num_normalize3(h);
            memcpy(p->h, h, sizeof h);
        }
        cnt++;
    }
    ctx->light_prep_count = cnt;
}

/* per light: the unit spot direction, and whether the specular product is
** zero (such a light skips h and pow entirely) */
static void update_lights(GlesContext *ctx)
{
    const Material *m = &ctx->material;
    for (int i = 0; i < GLES_MAX_LIGHTS; i++) {
        Light *l = &ctx->lights[i];
        memcpy(l->unit_spot_direction, l->n_spot_direction, sizeof l->unit_spot_direction);
        num_normalize3(l->unit_spot_direction);
        l->has_specular = 0;
        for (int k = 0; k < 3; k++)
            if (num_mul(m->n_specular[k], l->n_specular[k]) != NUM_ZERO)
                l->has_specular = 1;
    }
}

void light_validate(GlesContext *ctx)
{
    ctx->active_lights = 0;
    for (int i = 0; i < GLES_MAX_LIGHTS; i++)
        if (ctx->light_enabled[i])
            ctx->active_lights |= 1u << i;
    ctx->two_sided = ctx->lighting && ctx->light_model_two_side;
    /* the normal matrices serve lighting and texture coordinate generation */
    if (!ctx->lighting && !texgen_any(ctx))
        return;
    /* the lights and the material: light positions are in eye space
    ** already, so a new modelview leaves these alone (turning lighting on
    ** marks DIRTY_LIGHT) */
    if (ctx->lighting && (ctx->dirty & DIRTY_LIGHT)) {
        update_lights(ctx);
        prepare_lights(ctx);
    }
    normal_matrix_of(ctx->modelview.top->n, ctx->normal_matrix, &ctx->rescale);
    if (ctx->matrix_palette)
        for (int i = 0; i < GLES_MAX_PALETTE_MATRICES; i++)
            normal_matrix_of(ctx->palette[i].n, ctx->palette_normal[i], &ctx->palette_rescale[i]);
}

/* {====================================================================
** the lighting equation, per vertex */

/* |v| robustly: largest component times the length of v / that component */
static NUM length3(const NUM v[3])
{
    NUM m = num_max(num_abs(v[0]), num_max(num_abs(v[1]), num_abs(v[2])));
    if (m == NUM_ZERO)
        return NUM_ZERO;
    NUM u[3] = { num_div(v[0], m), num_div(v[1], m), num_div(v[2], m) };
    return num_mul(m, num_sqrt(num_dot(u, 1, u, 1, 3)));
}

static void light_side(const GlesContext *ctx, const NUM n[3], const NUM v[3], const NUM *amb_cm,
                       const NUM *dif_cm, NUM out[4])
{
    const Material *m = &ctx->material;
    NUM acc[3];
    for (int k = 0; k < 3; k++)
        acc[k] = num_add(m->n_emission[k], num_mul(amb_cm[k], ctx->n_light_model_ambient[k]));
    for (unsigned int bits = ctx->active_lights; bits; bits &= bits - 1) {
        const Light *l = &ctx->lights[__builtin_ctz(bits)];
        NUM vp[3], att = NUM_ONE;
        if (l->n_position[3] != NUM_ZERO) {
            /* positional: VP = P - V, attenuated by its length */
            NUM pw = l->n_position[3];
            for (int k = 0; k < 3; k++)
                vp[k] = num_sub(pw == NUM_ONE ? l->n_position[k] : num_div(l->n_position[k], pw), v[k]);
            const NUM *ka = l->n_attenuation;
            if (ka[1] != NUM_ZERO || ka[2] != NUM_ZERO || ka[0] != NUM_ONE) {
                NUM d = length3(vp);
                /* k2 d first, then times d: d^2 alone overflows 16.16 beyond
                ** d = 181 while k2 d^2 usually does not */
                NUM den = num_add(ka[0], num_add(num_mul(ka[1], d), num_mul(num_mul(ka[2], d), d)));
                att = num_recip(den);
            }
        } else {
            for (int k = 0; k < 3; k++)
                vp[k] = l->n_position[k];
        }
        if (!num_normalize3(vp))
            continue; /* the light is at the vertex: no direction */
        NUM spot = NUM_ONE;
        if (l->spot_cutoff != 180.0) {
            NUM cosang = num_neg(num_dot(vp, 1, l->unit_spot_direction, 1, 3)); /* -VP . s */
            if (cosang < l->n_cos_cutoff)
                continue; /* outside the cone: contributes nothing */
            spot = num_pow(cosang, l->n_spot_exponent);
        }
        NUM scale = num_mul(att, spot);
        NUM ndotvp = num_dot(n, 1, vp, 1, 3);
        NUM term[3];
        for (int k = 0; k < 3; k++)
            term[k] = num_mul(amb_cm[k], l->n_ambient[k]);
        if (ndotvp > NUM_ZERO) {
            for (int k = 0; k < 3; k++)
                term[k] = num_add(term[k], num_mul(ndotvp, num_mul(dif_cm[k], l->n_diffuse[k])));
            /* h = VP + (0, 0, 1), no local viewer in ES */
            NUM h[3] = { vp[0], vp[1], num_add(vp[2], NUM_ONE) };
            if (l->has_specular && num_normalize3(h)) {
                NUM ndoth = num_dot(n, 1, h, 1, 3);
                if (ndoth > NUM_ZERO) {
                    NUM sp = num_pow(ndoth, m->n_shininess);
                    for (int k = 0; k < 3; k++)
                        term[k] = num_add(term[k], num_mul(sp, num_mul(m->n_specular[k], l->n_specular[k])));
                }
            }
        }
        for (int k = 0; k < 3; k++)
            acc[k] = num_add(acc[k], num_mul(scale, term[k]));
    }
    for (int k = 0; k < 3; k++)
        out[k] = num_clamp01(acc[k]);
    out[3] = num_clamp01(dif_cm[3]); /* alpha is the diffuse material's */
}

void light_vertex(const GlesContext *ctx, const NUM eye[4], const NUM n[3], const NUM color[4], NUM front[4],
                  NUM back[4])
{
    NUM v[3];
    if (eye[3] == NUM_ONE || eye[3] == NUM_ZERO) {
        v[0] = eye[0]; v[1] = eye[1]; v[2] = eye[2];
    } else {
        for (int k = 0; k < 3; k++)
            v[k] = num_div(eye[k], eye[3]);
    }
    const Material *m = &ctx->material;
    const NUM *amb = ctx->color_material ? color : m->n_ambient;
    const NUM *dif = ctx->color_material ? color : m->n_diffuse;
    light_side(ctx, n, v, amb, dif, front);
    if (back) {
        NUM nb[3] = { num_neg(n[0]), num_neg(n[1]), num_neg(n[2]) };
        light_side(ctx, nb, v, amb, dif, back);
    }
}

/* {====================================================================
** the lighting equation, per batch */

/* n . u for lane i of a structure-of-arrays normal: num_dot's arithmetic */
static inline NUM lane_dot(NUM n[3][LIGHT_BATCH], int i, const NUM u[3])
{
    NUM t[3] = { n[0][i], n[1][i], n[2][i] };
    return num_dot(t, 1, u, 1, 3);
}

/* a directional light's term for every lane: only n . VP, n . h and the
** specular power depend on the vertex. `cm`: COLOR_MATERIAL (a constant
** at each call, so each instance loses the test). `simd`: the AVX2 kernels
** of vertex_avx2.h (every lane up to cnt, padding included), the
** specular power among them (vx_specular_avx2) */
static inline void directional_batch(const LightPrep *p, NUM shin, LightBatch *b, NUM n[3][LIGHT_BATCH],
                                     NUM acc[3][LIGHT_BATCH], int cnt, const int cm, int simd)
{
    const Light *l = p->l;
#if VERTEX_AVX2
    if (simd && !p->specular) {
        vx_dir_fused_avx2(p->p, n, b->col, l->n_ambient, l->n_diffuse, p->amb, p->dif, cm, p->scale, acc, cnt);
        return;
    }
#endif
    NUM ndotvp[LIGHT_BATCH], ndoth[LIGHT_BATCH];
    /* num_dot(n, 1, VP, 1, 3) lane by lane (the products commute) */
    vx_dot3_lanes(simd, p->p[0], p->p[1], p->p[2], n[0], n[1], n[2], ndotvp, cnt);
    if (p->specular)
        vx_dot3_lanes(simd, p->h[0], p->h[1], p->h[2], n[0], n[1], n[2], ndoth, cnt);
#if VERTEX_AVX2
    if (simd) {
        NUM term[3][LIGHT_BATCH];
        vx_dir_terms_avx2(ndotvp, b->col, l->n_ambient, l->n_diffuse, p->amb, p->dif, cm, term, cnt);
        if (p->specular)
            vx_specular_avx2(ndotvp, ndoth, shin, p->spec, term, b->n);
        vx_scale_add_avx2(p->scale, term, acc, cnt);
        return;
    }
#endif
    for (int i = 0; i < b->n; i++) {   /* branches and pow: scalar, padding skipped */
        NUM term[3];
        for (int k = 0; k < 3; k++)
            term[k] = cm ? num_mul(b->col[k][i], l->n_ambient[k]) : p->amb[k];
        if (ndotvp[i] > NUM_ZERO) {
            for (int k = 0; k < 3; k++)
                term[k] = num_add(term[k], num_mul(ndotvp[i], cm ? num_mul(b->col[k][i], l->n_diffuse[k]) : p->dif[k]));
            if (p->specular && ndoth[i] > NUM_ZERO) {
                NUM sp = num_pow(ndoth[i], shin);
                for (int k = 0; k < 3; k++)
                    term[k] = num_add(term[k], num_mul(sp, p->spec[k]));
            }
        }
        for (int k = 0; k < 3; k++)
            acc[k][i] = num_add(acc[k][i], num_mul(p->scale, term[k]));
    }
}

int light_debug_directional(int simd, int n, const int32_t *m, const int32_t *in, int32_t *out)
{
    if (n < 0 || n > LIGHT_BATCH || n % LIGHT_LANES != 0)
        return 0;
    /* VP = (1, 0, 0) and h = (0, 1, 0), so the lanes' normals (d, h, 0)
    ** give n . VP = d and n . h = h exactly (one product by 2^16) */
    Light l;
    LightPrep p;
    LightBatch b;
    memset(&l, 0, sizeof l);
    memset(&p, 0, sizeof p);
    memset(&b, 0, sizeof b);
    NUM nrm[3][LIGHT_BATCH] = { { 0 } }, acc[3][LIGHT_BATCH];
    for (int k = 0; k < 3; k++) {
        l.n_ambient[k] = m[2];
        l.n_diffuse[k] = m[3];
        p.amb[k] = m[0];
        p.dif[k] = m[1];
        p.spec[k] = m[6];
    }
    p.l = &l;
    p.p[0] = NUM_ONE;
    p.h[1] = NUM_ONE;
    p.scale = m[4];
    p.specular = m[7] != 0;
    b.n = n;
    for (int i = 0; i < n; i++) {
        nrm[0][i] = in[i];
        nrm[1][i] = in[192 + i];
        for (int k = 0; k < 3; k++) {
            b.col[k][i] = in[64 + i];
            acc[k][i] = in[128 + i];
        }
    }
    simd = simd && simd_detect() >= SIMD_AVX2;
    if (m[9])
        directional_batch(&p, m[5], &b, nrm, acc, n, 1, simd);
    else
        directional_batch(&p, m[5], &b, nrm, acc, n, 0, simd);
    for (int i = 0; i < n; i++)
        out[i] = acc[0][i];
    return 1;
}

/* a positional light's term for every lane: light_side's loop body with
** the light's branches taken once for the batch */
static inline void positional_batch(const LightPrep *p, NUM shin, LightBatch *b, NUM n[3][LIGHT_BATCH],
                                    NUM acc[3][LIGHT_BATCH], const int cm)
{
    const Light *l = p->l;
    const NUM *ka = l->n_attenuation;
    for (int i = 0; i < b->n; i++) {   /* scalar: padding lanes would only cost */
        NUM vp[3], att = NUM_ONE;
        for (int k = 0; k < 3; k++)
            vp[k] = num_sub(p->p[k], b->v[k][i]);
        if (p->attenuate) {
            NUM d = length3(vp);
            NUM den = num_add(ka[0], num_add(num_mul(ka[1], d), num_mul(num_mul(ka[2], d), d)));
            att = num_recip(den);
        }
        if (!num_normalize3(vp))
            continue;
        NUM spot = NUM_ONE;
        if (p->spot) {
            NUM cosang = num_neg(num_dot(vp, 1, l->unit_spot_direction, 1, 3));
            if (cosang < l->n_cos_cutoff)
                continue;
            spot = num_pow(cosang, l->n_spot_exponent);
        }
        NUM scale = num_mul(att, spot);
        NUM ndotvp = lane_dot(n, i, vp);
        NUM term[3];
        for (int k = 0; k < 3; k++)
            term[k] = cm ? num_mul(b->col[k][i], l->n_ambient[k]) : p->amb[k];
        if (ndotvp > NUM_ZERO) {
            for (int k = 0; k < 3; k++)
                term[k] = num_add(term[k], num_mul(ndotvp, cm ? num_mul(b->col[k][i], l->n_diffuse[k]) : p->dif[k]));
            NUM h[3] = { vp[0], vp[1], num_add(vp[2], NUM_ONE) };
            if (p->specular && num_normalize3(h)) {
                NUM ndoth = lane_dot(n, i, h);
                if (ndoth > NUM_ZERO) {
                    NUM sp = num_pow(ndoth, shin);
                    for (int k = 0; k < 3; k++)
                        term[k] = num_add(term[k], num_mul(sp, p->spec[k]));
                }
            }
        }
        for (int k = 0; k < 3; k++)
            acc[k][i] = num_add(acc[k][i], num_mul(scale, term[k]));
    }
}

#if VERTEX_AVX2 || VERTEX_AVX2_FP
/* positional_batch through the build's kernel (vx_positional_avx2 or
** vx_positional_fp_avx2: every lane of the padded batch, padding lanes
** left as they are) */
static void positional_batch_avx2(const LightPrep *p, NUM shin, LightBatch *b, NUM n[3][LIGHT_BATCH],
                                  NUM acc[3][LIGHT_BATCH], int cnt, int cm)
{
    const Light *l = p->l;
    VxPositional L;
    for (int k = 0; k < 3; k++) {
        L.p[k] = p->p[k];
        L.ka[k] = l->n_attenuation[k];
        L.sdir[k] = l->unit_spot_direction[k];
        L.lamb[k] = l->n_ambient[k];
        L.ldif[k] = l->n_diffuse[k];
        L.amb[k] = p->amb[k];
        L.dif[k] = p->dif[k];
        L.spec[k] = p->spec[k];
    }
    L.cos_cutoff = l->n_cos_cutoff;
    L.spot_exp = l->n_spot_exponent;
    L.shin = shin;
    L.attenuate = p->attenuate;
    L.spot = p->spot;
    L.specular = p->specular;
#if VERTEX_AVX2
    vx_positional_avx2(&L, b->v, n, b->col, acc, b->n, cnt, cm);
#else
    vx_positional_fp_avx2(&L, b->v, n, b->col, acc, b->n, cnt, cm);
#endif
}
#endif

/* the hook's numbers: 16.16 in the fixed build, float bit patterns in the
** float builds (NaN, infinities and -0 included) */
static NUM debug_num(int32_t x)
{
#if NUM_IS_FIXED
    return x;
#else
    float f;
    memcpy(&f, &x, sizeof f);
    return (NUM)f;
#endif
}

int light_debug_positional(int simd, int n, const int32_t *m, const int32_t *in, int32_t *out)
{
    if (n < 0 || n > LIGHT_BATCH || n % LIGHT_LANES != 0 || m[31] < 0 || m[31] > n)
        return 0;
    Light l;
    LightPrep p;
    LightBatch b;
    memset(&l, 0, sizeof l);
    memset(&p, 0, sizeof p);
    memset(&b, 0, sizeof b);
    NUM nrm[3][LIGHT_BATCH], acc[3][LIGHT_BATCH];
    for (int k = 0; k < 3; k++) {
        p.p[k] = debug_num(m[k]);
        l.n_attenuation[k] = debug_num(m[3 + k]);
        l.unit_spot_direction[k] = debug_num(m[6 + k]);
        l.n_ambient[k] = debug_num(m[12 + k]);
        l.n_diffuse[k] = debug_num(m[15 + k]);
        p.amb[k] = debug_num(m[18 + k]);
        p.dif[k] = debug_num(m[21 + k]);
        p.spec[k] = debug_num(m[24 + k]);
    }
    l.n_cos_cutoff = debug_num(m[9]);
    l.n_spot_exponent = debug_num(m[10]);
    const NUM shin = debug_num(m[11]);
    p.l = &l;
    p.positional = 1;
    p.attenuate = m[27] != 0;
    p.spot = m[28] != 0;
    p.specular = m[29] != 0;
    b.n = m[31];
    for (int k = 0; k < 3; k++)
        for (int i = 0; i < n; i++) {
            b.v[k][i] = debug_num(in[64 * k + i]);
            nrm[k][i] = debug_num(in[192 + 64 * k + i]);
            b.col[k][i] = debug_num(in[384 + 64 * k + i]);
            acc[k][i] = debug_num(in[576 + 64 * k + i]);
        }
    simd = simd && simd_detect() >= SIMD_AVX2;
#if VERTEX_AVX2 || VERTEX_AVX2_FP
    if (simd)
        positional_batch_avx2(&p, shin, &b, nrm, acc, n, m[30] != 0);
    else
#endif
    if (m[30])
        positional_batch(&p, shin, &b, nrm, acc, 1);
    else
        positional_batch(&p, shin, &b, nrm, acc, 0);
    /* out: the accumulators, rows of 64 NUMs as stored */
    for (int k = 0; k < 3; k++)
        memcpy((char *)out + (size_t)k * 64 * sizeof(NUM), acc[k], (size_t)n * sizeof(NUM));
    return 1;
}

/* light_side for a batch: lights outer, vertices inner, so each light's
** constants and branches are set up once per batch; every vertex still
** accumulates its lights in the order of their numbers */
static inline void side_batch(const GlesContext *ctx, LightBatch *b, NUM n[3][LIGHT_BATCH],
                              NUM out[4][LIGHT_BATCH], const int cm)
{
    const Material *m = &ctx->material;
    const int cnt = (b->n + LIGHT_LANES - 1) / LIGHT_LANES * LIGHT_LANES;
    NUM acc[3][LIGHT_BATCH];
    for (int k = 0; k < 3; k++)
        NUM_FOR_LANES(i, cnt)
            acc[k][i] = cm ? num_add(m->n_emission[k], num_mul(b->col[k][i], ctx->n_light_model_ambient[k]))
                           : ctx->light_base[k];
    for (int j = 0; j < ctx->light_prep_count; j++) {
        const LightPrep *p = &ctx->light_prep[j];
        if (p->positional) {
#if VERTEX_AVX2 || VERTEX_AVX2_FP
            if (ctx_simd(ctx) >= SIMD_AVX2) {
                positional_batch_avx2(p, m->n_shininess, b, n, acc, cnt, cm);
                continue;
            }
#endif
            positional_batch(p, m->n_shininess, b, n, acc, cm);
        } else {
            directional_batch(p, ctx->material.n_shininess, b, n, acc, cnt, cm, ctx_simd(ctx) >= SIMD_AVX2);
        }
    }
    for (int k = 0; k < 3; k++)
        NUM_FOR_LANES(i, cnt)
            out[k][i] = num_clamp01(acc[k][i]);
    NUM_FOR_LANES(i, cnt)
        out[3][i] = num_clamp01(cm ? b->col[3][i] : m->n_diffuse[3]);  /* alpha is the diffuse material's */
}

void light_batch(const GlesContext *ctx, LightBatch *b, int two_sided)
{
    NUM nb[3][LIGHT_BATCH];
    const int cnt = (b->n + LIGHT_LANES - 1) / LIGHT_LANES * LIGHT_LANES;
    if (two_sided)
        for (int k = 0; k < 3; k++)
            NUM_FOR_LANES(i, cnt)
                nb[k][i] = num_neg(b->nrm[k][i]);
    if (ctx->color_material) {
        side_batch(ctx, b, b->nrm, b->out[0], 1);
        if (two_sided)
            side_batch(ctx, b, nb, b->out[1], 1);
    } else {
        side_batch(ctx, b, b->nrm, b->out[0], 0);
        if (two_sided)
            side_batch(ctx, b, nb, b->out[1], 0);
    }
}
