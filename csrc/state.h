/*
** state.h -- the context structure every stage reads, and the limits.
** Owns: the layout of GlesContext (API state as the application set it,
**       plus derived state recomputed on validation), dirty bits.
** Conventions: API values are stored as double (what queries return) beside
**       their NUM form (what the pipeline computes with).
*/
#ifndef GLES_STATE_H
#define GLES_STATE_H

#include <stddef.h>
#include <stdint.h>
#include "num.h"
#include "gles_core.h"
#include "glenums.h"
#include "simd.h"
#include "pool.h"

/* {====================================================================
** limits (each at or above the spec's minimum, Tables 6.20-6.22) */
#define GLES_MAX_TEXTURE_UNITS 4
/* room for the fused span stage's per-triangle constants (Avx2ModWrite) */
#define GLES_FUSED_SETUP_BYTES 2048
#define GLES_PERSP_SETUP_BYTES 640
/* room for the stencil and depth tests' per-primitive setup (Avx2TestsSetup) */
#define GLES_TESTS_SETUP_BYTES 1024
/* fragments of one flat colour's blend before its table is built: building
** it (1024 entries) then costs at most what those fragments did */
#define GLES_FLAT_TABLE_AFTER 1024
#define GLES_MAX_CLIP_PLANES 6
#define GLES_MODELVIEW_STACK_DEPTH 32
#define GLES_PROJECTION_STACK_DEPTH 4
#define GLES_TEXTURE_STACK_DEPTH 4
#define GLES_MAX_VIEWPORT_DIM 4096
#define GLES_MAX_FRAMEBUFFER_DIM 4096
#define GLES_MAX_PALETTE_MATRICES 32  /* OES_matrix_palette: at least 9 */
#define GLES_MAX_VERTEX_UNITS 4       /* OES_matrix_palette: at least 3 */
#define GLES_SUBPIXEL_BITS 8
#define GLES_SUBPIXEL_ONE (1 << GLES_SUBPIXEL_BITS)

/* debug flags (gles_debug_set) */
#define GLES_DEBUG_GENERIC_SPANS 1
#define GLES_DEBUG_FLIP_TIE_RULE 2
#define GLES_DEBUG_DROP_LAST_PIXEL 4
#define GLES_DEBUG_VERTEX_REFERENCE 8  /* per-vertex reference path instead of batches */
#define GLES_DEBUG_BASELINE_SIMD 16    /* the baseline span stages even where AVX2 runs */
#define GLES_DEBUG_AVX2_SIMD 32        /* at most the AVX2 instance where AVX-512 runs */
#define GLES_DEBUG_THREADS_ALWAYS 64   /* threaded draws however few pixels and vertices */

/* {====================================================================
** matrices */
enum { MAT_GENERAL = 0, MAT_AFFINE, MAT_IDENTITY };

typedef struct Matrix {
    double d[16];   /* as the application built it, column-major */
    NUM n[16];      /* the same matrix built in this build's arithmetic */
    int kind;       /* MAT_*: lets transforms skip work */
} Matrix;

typedef struct MatrixStack {
    Matrix *top;
    int depth;      /* entries in use, 1..capacity */
    int capacity;
    Matrix entries[GLES_MODELVIEW_STACK_DEPTH];
} MatrixStack;

/* {====================================================================
** vertex arrays and buffer objects */
typedef struct BufferObject {
    unsigned int name;
    uint8_t *data;
    int64_t size;
    unsigned int usage;
    /* OES_mapbuffer, EXT_map_buffer_range: the mapped range and its access
    ** bits (MapBufferOES maps all of it, MAP_WRITE_BIT) */
    int mapped;
    unsigned int map_access;
    int64_t map_offset, map_length;
} BufferObject;

/* open-addressing map from GL names to objects (buffers now, textures later) */
typedef struct NameTable {
    unsigned int *keys;   /* 0 marks an empty slot, ~0u a deleted one */
    void **values;
    uint32_t capacity;    /* power of two */
    uint32_t used;        /* live + deleted slots */
    unsigned int next_name;
} NameTable;

enum { ARR_VERTEX = 0, ARR_NORMAL, ARR_COLOR, ARR_POINT_SIZE, ARR_MATRIX_INDEX, ARR_WEIGHT,
       ARR_TEXCOORD0, ARR_COUNT = ARR_TEXCOORD0 + GLES_MAX_TEXTURE_UNITS };

typedef struct ArrayState {
    int enabled;
    int size;               /* components */
    unsigned int type;
    int stride;             /* as given (0 = tightly packed) */
    int elem_bytes;         /* size * sizeof(type) */
    int step;               /* effective stride in bytes */
    const uint8_t *ptr;     /* client pointer, or offset into the buffer */
    int64_t nbytes;         /* client array length, -1 if unknown */
    BufferObject *buffer;   /* NULL for client memory */
    unsigned int buffer_name;
    /* range.c: largest |component| of a buffer-backed array, valid while
    ** range_cached and range_serial == the context's buffer_serial */
    double range_max;
    uint32_t range_serial;
    int range_cached;
} ArrayState;

/* OES_vertex_array_object: the vertex array state of Tables 6.4-6.5 but
** CLIENT_ACTIVE_TEXTURE and ARRAY_BUFFER_BINDING. The bound object's state
** lives in the context (ctx->arrays, ctx->element_buffer); an object holds
** it while another is bound, and ctx->vao_default holds name 0's */
typedef struct VertexArrayState {
    ArrayState arrays[ARR_COUNT];
    BufferObject *element_buffer;
} VertexArrayState;

typedef struct VertexArrayObject {
    unsigned int name;
    int ever_bound;             /* IsVertexArrayOES: named by Gen, then bound */
    VertexArrayState state;
} VertexArrayObject;

/* {====================================================================
** lighting state (§2.12.1); positions and directions in eye space */
#define GLES_MAX_LIGHTS 8

typedef struct Light {
    double ambient[4], diffuse[4], specular[4], position[4], spot_direction[3];
    double spot_exponent, spot_cutoff, attenuation[3];
    NUM n_ambient[4], n_diffuse[4], n_specular[4], n_position[4], n_spot_direction[3];
    NUM n_spot_exponent, n_cos_cutoff, n_attenuation[3];
    NUM unit_spot_direction[3];     /* derived: normalised */
    int has_specular;               /* derived: s_cm * s_cli is not zero */
} Light;

/* what one enabled light contributes, prepared on validation so that the
** per-vertex loop (light_batch) does only what depends on the vertex;
** every value is computed exactly as the per-vertex equation computes it */
typedef struct LightPrep {
    const Light *l;
    int positional;     /* else directional: p, h, scale are constants */
    int attenuate;      /* positional with attenuation other than (1, 0, 0) */
    int spot;           /* positional with a cone (directional: folded in scale) */
    int specular;       /* has_specular and, directional, a defined h */
    NUM p[3];           /* positional: P / w_P; directional: unit VP */
    NUM h[3];           /* directional: the unit half vector */
    NUM scale;          /* directional: att * spot */
    NUM amb[3], dif[3]; /* a_cm * a_cli, d_cm * d_cli with the material's a, d */
    NUM spec[3];        /* s_cm * s_cli */
} LightPrep;

typedef struct Material {
    double ambient[4], diffuse[4], specular[4], emission[4], shininess;
    NUM n_ambient[4], n_diffuse[4], n_specular[4], n_emission[4], n_shininess;
} Material;

/* {====================================================================
** textures (§3.7); texels are stored expanded to RGBA8888 (R in the low
** byte) with the base format kept for the environment */
#define GLES_MAX_TEXTURE_SIZE 2048
#define GLES_MAX_TEXTURE_LEVELS 12      /* 2048 .. 1 */

/* the default memory budget of a context's textures and buffers */
#define GLES_DEFAULT_MEMORY_LIMIT ((int64_t)256 << 20)

typedef struct TexImage {
    int width, height;                  /* 0 while undefined */
    uint32_t *texels;
} TexImage;

typedef struct Texture {
    unsigned int name;
    TexImage level[GLES_MAX_TEXTURE_LEVELS];
    unsigned int format;                /* base format of level 0 */
    unsigned int level_format[GLES_MAX_TEXTURE_LEVELS];
    unsigned int min_filter, mag_filter, wrap_s, wrap_t;
    int generate_mipmap;
    int crop[4];
    int level_limit;                    /* TEXTURE_MAX_LEVEL_APPLE (APPLE_texture_max_level) */
    double max_aniso;                   /* TEXTURE_MAX_ANISOTROPY_EXT (EXT_texture_filter_anisotropic) */
    int paletted;                       /* specified with CompressedTexImage2D */
    /* OES_texture_cube_map: the target a name is bound to for life (0 until
    ** first bound); a cube map keeps its six faces' images in face[i] (in
    ** the order POSITIVE_X, NEGATIVE_X, ..., NEGATIVE_Z), each a Texture
    ** whose parameters are copies of the cube map's (texture_update); a
    ** face points back at its cube map */
    unsigned int target;
    struct Texture *face[6];
    struct Texture *cube;
    /* derived by texture_complete(): */
    int complete;
    int max_level;                      /* q: the last level sampled */
} Texture;

/* a 16-bit colour buffer's channels, R, G, B, A, as GL's packed types
** (red in the high bits): each one's width and lowest bit in the word, 0
** bits for none (RGB565's alpha) */
typedef struct ColorLayout {
    int bits[4], shift[4];
} ColorLayout;

static inline const ColorLayout *color_layout16(int format)
{
    static const ColorLayout rgb565 = { { 5, 6, 5, 0 }, { 11, 5, 0, 0 } };
    static const ColorLayout rgba4444 = { { 4, 4, 4, 4 }, { 12, 8, 4, 0 } };
    static const ColorLayout rgba5551 = { { 5, 5, 5, 1 }, { 11, 6, 1, 0 } };
    return format == GLES_COLOR_RGBA4444 ? &rgba4444 : format == GLES_COLOR_RGBA5551 ? &rgba5551 : &rgb565;
}

/* bytes of a pixel of a colour format (GLES_COLOR_*) */
static inline int color_bytes(int format) { return format == GLES_COLOR_RGBA8888 ? 4 : 2; }

/* the bits of channel i (0..3) of a colour format */
static inline int color_channel_bits(int format, int i)
{
    return format == GLES_COLOR_RGBA8888 ? 8 : color_layout16(format)->bits[i];
}

/* the packed word's bits of the channels whose colour mask is off: those
** a write keeps as stored */
static inline uint32_t color_mask_keep(int format, const unsigned char mask[4])
{
    uint32_t keep = 0;
    for (int i = 0; i < 4; i++) {
        if (mask[i])
            continue;
        if (format == GLES_COLOR_RGBA8888) {
            keep |= 0xFFu << (8 * i);
        } else {
            const ColorLayout *l = color_layout16(format);
            keep |= ((1u << l->bits[i]) - 1) << l->shift[i];
        }
    }
    return keep;
}

/* channel i of a 16-bit word expanded to 8 bits, c * 255 / (2^bits - 1)
** rounded (255 where the format has none) */
static inline uint32_t color_channel8(const ColorLayout *l, int i, uint32_t word)
{
    if (!l->bits[i])
        return 255;
    const uint32_t max = (1u << l->bits[i]) - 1;
    return (((word >> l->shift[i]) & max) * 255 + max / 2) / max;
}

/* a 16-bit format's words to 8-bit channels by table (color_channel8's
** rounding, 255 for a channel the format lacks): ReadPixels' and CopyTex's
** rows, the table made once per command */
typedef struct ColorExpand8 {
    const ColorLayout *layout;
    uint32_t max[4];            /* each channel's mask after its shift */
    uint8_t x8[4][64];          /* [channel][stored value] */
} ColorExpand8;

static inline void color_expand8_init(ColorExpand8 *e, int format)
{
    const ColorLayout *l = e->layout = color_layout16(format);
    for (int i = 0; i < 4; i++) {
        e->max[i] = (1u << l->bits[i]) - 1;
        for (uint32_t c = 0; c < 64; c++)
            e->x8[i][c] = (uint8_t)color_channel8(l, i, (c & e->max[i]) << l->shift[i]);
    }
}

static inline void color_expand8(const ColorExpand8 *e, uint32_t word, uint8_t out[4])
{
    for (int i = 0; i < 4; i++)
        out[i] = e->x8[i][(word >> e->layout->shift[i]) & e->max[i]];
}

/* a colour format's implementation read pair (OES_read_format): its own
** packed type, or for RGBA8888, whose byte order is RGBA already, the pair
** a program cannot otherwise have (EXT_read_format_bgra's BGRA_EXT) */
static inline void color_read_pair(int format, unsigned int *gl_format, unsigned int *gl_type)
{
    switch (format) {
    case GLES_COLOR_RGB565: *gl_format = GL_RGB, *gl_type = GL_UNSIGNED_SHORT_5_6_5; break;
    case GLES_COLOR_RGBA4444: *gl_format = GL_RGBA, *gl_type = GL_UNSIGNED_SHORT_4_4_4_4; break;
    case GLES_COLOR_RGBA5551: *gl_format = GL_RGBA, *gl_type = GL_UNSIGNED_SHORT_5_5_5_1; break;
    default: *gl_format = GL_BGRA_EXT, *gl_type = GL_UNSIGNED_BYTE; break;
    }
}

/* OES_framebuffer_object: a renderbuffer's image (one of color, depth or
** stencil storage, or depth and stencil for DEPTH24_STENCIL8_OES) */
typedef struct Renderbuffer {
    unsigned int name;
    unsigned int format;        /* sized internal format; 0 before RenderbufferStorageOES */
    int width, height;
    void *color;                /* uint32 RGBA8888 or uint16 RGB565, RGBA4444, RGBA5551, as the window's */
    uint32_t *depth;
    uint8_t *stencil;
    int64_t bytes;              /* charged to the memory budget */
} Renderbuffer;

/* an attachment point: type GL_NONE_OES, GL_TEXTURE or GL_RENDERBUFFER_OES */
typedef struct FboAttachment {
    unsigned int type, name;
    Texture *tex;
    int level;
    Renderbuffer *rb;
} FboAttachment;

enum { FBO_COLOR, FBO_DEPTH, FBO_STENCIL, FBO_POINTS };

typedef struct Framebuffer {
    unsigned int name;
    FboAttachment at[FBO_POINTS];
} Framebuffer;

/* the buffers commands draw into and read: the window's, or a complete
** framebuffer object's (fbo_sync) */
typedef struct DrawBuffers {
    int width, height;
    int color_format;           /* GLES_COLOR_* */
    int color_alpha;            /* the color buffer keeps alpha (not RGB565, RGB8, an RGB texture) */
    int depth_bits, stencil_bits;
    uint32_t depth_max;
    void *color;
    uint32_t *depth;
    uint8_t *stencil;
} DrawBuffers;

typedef struct TexUnit {
    int enabled_2d, enabled_cube;       /* TEXTURE_2D, TEXTURE_CUBE_MAP_OES */
    Texture *bound_2d;                  /* never NULL: name 0 is ctx->default_texture */
    Texture *bound_cube;                /* never NULL: name 0 is ctx->default_cube */
    /* derived (texture_unit_update): either target enabled, and the texture
    ** sampled by the precedence of §3.8.10 (the cube map's when enabled) */
    int enabled;
    Texture *bound;
    int texgen;                         /* TEXTURE_GEN_STR_OES */
    unsigned int texgen_mode;           /* TEXTURE_GEN_MODE_OES */
    unsigned int env_mode;
    double env_color[4];
    NUM n_env_color[4];
    unsigned int combine_rgb, combine_alpha;
    unsigned int src_rgb[3], src_alpha[3], op_rgb[3], op_alpha[3];
    double rgb_scale, alpha_scale;
    double lod_bias;                    /* TEXTURE_LOD_BIAS_EXT (EXT_texture_lod_bias), as specified */
    int coord_replace;                  /* OES_point_sprite */
} TexUnit;

/* {====================================================================
** vertices after transformation */
typedef struct Vertex {
    NUM clip[4];
    NUM eye[4];
    FRAGV color[4];         /* front colour (lit, or the vertex colour), in [0,1] */
    FRAGV color_back[4];    /* back colour, with two-sided lighting */
    NUM tex[GLES_MAX_TEXTURE_UNITS][4];
    NUM point_size;
    NUM fog;                /* fog factor f, or |z_eye| when fog is per fragment */
    unsigned int outcode;   /* bit per violated clip plane */
    /* window position, valid when outcode == 0 or after clipping */
    int64_t wx, wy;         /* in subpixels */
    DEPTHV wz;              /* depth-buffer units */
    RecipW rw;              /* 1/w for perspective-correct weights */
} Vertex;

/* {====================================================================
** the fragment stage's view of a triangle (filled by raster.c) */
typedef struct TriSetup TriSetup;
typedef void (*SpanFunc)(struct GlesContext *ctx, const TriSetup *t, int y, int x0, int n);
typedef struct SpanBuf SpanBuf;
/* one stage of the fragment chain (span_chain.c), over a chunk of a span */
typedef void (*SpanStage)(struct GlesContext *ctx, const TriSetup *t, SpanBuf *b);
#define GLES_MAX_STAGES 16
/* texture coordinates of a pixel (texture.h) and a sampler over a run of
** fragments (texsample.c) */
typedef struct TexCoord TexCoord;
typedef void (*TexSpanSampler)(const Texture *tex, int n, const TexCoord *c, const TexCoord *dx,
                               const TexCoord *dy, FRAGV *out, size_t stride, const FRAGV *unorm);

/* the words of one flat colour's blend, a table per destination byte,
** built once that colour has blended GLES_FLAT_TABLE_AFTER fragments */
typedef struct FlatTable {
    FRAGV sterm[4], da;     /* the key: the source term and 1 - A */
    int blend;              /* 0: no key */
    int ready;
    int64_t seen;           /* fragments of the key blended without the table */
    uint32_t word[4][256];  /* [channel][byte]: that channel's result, in place */
} FlatTable;

/* {====================================================================
** the context */
/* the fixed build's stepped smooth spans' constants of one triangle
** (span.c's span_smooth_setup, span_fused.h's span_smooth_stepped) */
typedef struct SmoothStep {
    int ok;                     /* stepping applies to the triangle */
    int affine;
    int qs[3];                  /* wgt_persp's shifts (0 where its n_i is 0) */
    uint64_t r;                 /* wgt_linear's R */
    uint64_t lin_step[3];       /* e_i R from one column to the next (i = 1, 2) */
    uint64_t mant[3];           /* wgt_persp's mantissas (0 where n_i is 0) */
    uint64_t per_step[3];       /* e_i mant_i from one column to the next */
    int64_t zbase, dz1, dz2;    /* wgt_depth3 as zbase + l1 dz1 + l2 dz2 */
    FRAGV base[4], d1[4], d2[4];  /* the colour as v4_lerp_deltas takes it (the vector instance) */
} SmoothStep;

/* room for a threaded job's argument (raster_threaded), which the largest,
** DrawTex's rectangle, fits */
#define GLES_JOB_ARG_BYTES 4096

struct GlesContext {
    /* framebuffer */
    /* the buffers drawn into and read (the window's unless a framebuffer
    ** object is bound: fbo.c swaps them, as DrawBuffers) */
    int width, height;
    int color_format;           /* GLES_COLOR_* */
    int depth_bits, stencil_bits;
    uint32_t depth_max;         /* 2^depth_bits - 1 */
    void *color;                /* uint32 RGBA8888 (R in the low byte) or a uint16 format */
    uint32_t *depth;
    uint8_t *stencil;
    int color_alpha;            /* the color buffer keeps alpha */
    DrawBuffers window;         /* the window's, while an object is bound */
    NameTable framebuffers, renderbuffers;
    Framebuffer *fbo;           /* bound, NULL for the window */
    Renderbuffer *rbo;          /* bound renderbuffer */
    int color_mask_alpha;       /* ColorMask's alpha; color_mask[3] also needs color_alpha */
    int profile;
    uint64_t prim_serial;       /* counts primitive setups, from 1 */
    /* threads (gles_threads_set): a draw's primitives are rasterized by
    ** `threads` threads, each on the rows of its bands (raster_owns_row):
    ** the caller on this context with band_index 0, worker i on
    ** worker_ctx[i - 1], a copy of this context made for the draw with
    ** its own per-primitive caches; band_count is 1 outside such a draw */
    int threads;
    WorkPool *pool;
    GlesContext **worker_ctx;
    int band_index, band_count;
    /* a thread's rows in such a draw: y with y mod band_period in
    ** [band_lo, band_hi) (raster_owns_row); band_caller_rows, the
    ** caller's part of each period, moves with the balance of the last
    ** jobs (raster.c's raster_band_balance) */
    int band_period, band_lo, band_hi, band_caller_rows, band_votes;
    /* a threaded job whose workers may still be running after the command
    ** that started it returned (raster_threaded): raster_join waits for
    ** them before anything the workers read or write changes */
    int job_pending;
    unsigned long job_ticket;   /* its pool_wait ticket */
    int job_votes;              /* its end moves the bands (raster_join_next) */
    /* a threaded draw's primitives, kept until its vertex work is done
    ** (draw.c's Prim), and the vertices whose attributes they need */
    void *draw_prims;           /* Prim */
    void *draw_pend;            /* int64_t: their array indices */
    void *draw_pendv;           /* Vertex *: their slots */
    int64_t draw_prims_cap, draw_pend_cap, draw_pendv_cap;
    /* span_rect's s by column, width + 1 per unit (RectSetup.col_s) */
    TEXC *rect_s;
    /* the fused stage's setup for the primitive of serial fused_serial (0:
    ** none): whether its colours are in range, and its kernel's constants
    ** (an Avx2ModWrite, span_stages.h), which every chunk of it shares */
    uint64_t fused_serial;
    int fused_in_range;
    void *fused_setup;          /* GLES_FUSED_SETUP_BYTES, 64-byte aligned (its vectors load in place) */
    /* the stepped smooth spans' constants of the primitive of serial
    ** smooth_serial (0: none), which its rows share */
    uint64_t smooth_serial;
    SmoothStep smooth_step;
    /* the stencil and depth tests' setup (span_stages.h) for the primitive
    ** of serial tests_serial (0: none), GLES_TESTS_SETUP_BYTES, 64-byte aligned */
    uint64_t tests_serial;
    void *tests_setup;
    /* the stepped weights' constants (span_stages.h's PerspAffine) of the
    ** primitive of serial persp_serial (0: none), GLES_PERSP_SETUP_BYTES,
    ** 64-byte aligned */
    uint64_t persp_serial;
    void *persp_setup;

    unsigned int error;
    char message[256];
    /* KHR_debug (debug.c): DEBUG_OUTPUT_KHR, read wherever an error is
    ** recorded, and the rest of its state */
    int debug_output;
    struct DebugState *dbg;

    /* enables */
    int cull_enabled, depth_test, scissor_test;
    int clip_plane_enabled[GLES_MAX_CLIP_PLANES];
    int other_enables;          /* accepted caps whose stage is not built yet */
    unsigned int enable_bits;   /* every accepted cap's state, by index */

    /* rasterization and per-fragment state */
    int viewport[4];
    double depth_range[2];
    int scissor[4];
    double clear_color[4];
    double clear_depth;
    int clear_stencil;
    unsigned char color_mask[4];
    unsigned char depth_mask;
    unsigned int depth_func;
    unsigned int cull_mode, front_face, shade_model;
    unsigned int hints[4];      /* perspective, point smooth, line smooth, fog */

    /* per-fragment operations (§4.1) */
    int alpha_test, stencil_test, blend, dither, color_logic_op;
    unsigned int alpha_func;
    double alpha_ref;
    NUM n_alpha_ref;
    unsigned int stencil_func, stencil_fail, stencil_zfail, stencil_zpass;
    int stencil_ref;
    uint32_t stencil_value_mask, stencil_writemask;
    unsigned int blend_src_rgb, blend_dst_rgb, blend_src_alpha, blend_dst_alpha;
    unsigned int blend_eq_rgb, blend_eq_alpha;
    unsigned int logic_op;
    double sample_coverage_value;
    int sample_coverage_invert;


    /* points, lines and polygon offset (§3.3-3.5) */
    double point_size, line_width, point_size_min, point_size_max, point_fade_threshold;
    double point_attenuation[3];
    NUM n_point_size, n_point_size_min, n_point_size_max, n_point_attenuation[3];
    int point_smooth, line_smooth, point_sprite, polygon_offset_fill;
    double offset_factor, offset_units;

    /* fog (§3.8) */
    int fog;
    unsigned int fog_mode;
    double fog_density, fog_start, fog_end, fog_color[4];
    NUM n_fog_density, n_fog_start, n_fog_end, n_fog_color[4];
    NUM n_fog_scale;            /* 1 / (end - start) for LINEAR */
    int fog_per_fragment;       /* FOG_HINT NICEST */
    unsigned int hint_generate_mipmap;
    int pack_alignment, unpack_alignment;

    /* transformation */
    unsigned int matrix_mode;
    MatrixStack modelview, projection;
    MatrixStack texture[GLES_MAX_TEXTURE_UNITS];
    MatrixStack *current_stack;
    /* OES_matrix_palette: no stack, so a one-deep MatrixStack whose top is
    ** the current palette matrix */
    Matrix palette[GLES_MAX_PALETTE_MATRICES];
    MatrixStack palette_stack;
    unsigned int current_palette;
    int matrix_palette;         /* MATRIX_PALETTE_OES enabled */
    double clip_plane[GLES_MAX_CLIP_PLANES][4];   /* eye space, as queried */
    NUM clip_plane_n[GLES_MAX_CLIP_PLANES][4];
    unsigned int active_texture, client_active_texture;

    /* lighting */
    int lighting, color_material, normalize, rescale_normal;
    int light_enabled[GLES_MAX_LIGHTS];
    Light lights[GLES_MAX_LIGHTS];
    Material material;
    double light_model_ambient[4];
    NUM n_light_model_ambient[4];
    int light_model_two_side;

    /* current values */
    double cur_color[4], cur_normal[3], cur_tex[GLES_MAX_TEXTURE_UNITS][4];
    NUM cur_color_n[4], cur_normal_n[3], cur_tex_n[GLES_MAX_TEXTURE_UNITS][4];

    /* textures */
    TexUnit units[GLES_MAX_TEXTURE_UNITS];
    Texture default_texture;
    Texture default_cube;               /* name 0 of TEXTURE_CUBE_MAP_OES */
    NameTable textures;
    unsigned int cube_units;            /* derived: bit per sampling unit whose texture is a cube map */
    unsigned int texgen_units;          /* derived: bit per sampling unit with TEXTURE_GEN_STR_OES */
    unsigned int tex_units_on;          /* derived: bit per unit that samples */

    /* arrays */
    ArrayState arrays[ARR_COUNT];
    NameTable buffers;
    BufferObject *array_buffer, *element_buffer;
    uint32_t buffer_serial;     /* advances whenever any buffer's contents change */
    NameTable vaos;             /* VertexArrayObject by name (OES_vertex_array_object) */
    VertexArrayObject *vao;     /* the bound one, NULL for name 0 */
    VertexArrayState vao_default;   /* name 0's state while another is bound */

    /* the memory budget of texture images and buffer data together, in
    ** bytes (gles_memory_limit): an allocation past it is OUT_OF_MEMORY */
    int64_t mem_used, mem_limit;

    /* the per-draw overflow rule (range.c): GLES_RANGE_* mode, counts and
    ** the last violation's c, s, t and c*s + t */
    int range_mode;
    int64_t range_draws, range_violations;
    double range_last[4];
    unsigned int range_arrays;          /* bit per ARR_* holding a value >= 32768 */
    double range_array_max[ARR_COUNT];

    /* derived state, valid when dirty == 0 */
    unsigned int dirty;
    NUM mvp[16];                /* projection * modelview */
    int mvp_kind;
    int mvp_stale;              /* a matrix changed since mvp was formed */
    int need_eye;               /* user clip planes, lighting, fog or texgen need eye coordinates */
    NUM normal_matrix[9];       /* inverse transpose of the modelview's 3x3, row-major */
    NUM rescale;                /* RESCALE_NORMAL factor */
    NUM palette_normal[GLES_MAX_PALETTE_MATRICES][9];  /* the same per palette matrix */
    NUM palette_rescale[GLES_MAX_PALETTE_MATRICES];
    int two_sided;              /* lighting with LIGHT_MODEL_TWO_SIDE */
    unsigned int active_lights; /* bit per enabled light */
    LightPrep light_prep[GLES_MAX_LIGHTS];  /* the enabled lights that can contribute */
    int light_prep_count;
    NUM light_base[3];          /* e_cm + a_cm * a_cs with the material's a */
    unsigned int clip_mask;     /* outcode bits that can be set */
    SpanFunc span;              /* chosen for the current state */
    SpanFunc span_const;        /* the same state with a constant colour */
    const char *span_name;
    SpanStage chain[GLES_MAX_STAGES];   /* the chain's stages, when span is span_chain */
    int chain_len;
    int chain_coords_unit;      /* the unit whose coordinates stage_persp forms, else -1 */
    int chain_coords_tx_unit;   /* ... and the unit whose it forms into b->tx, else -1 */
    int chain_lod_unit;         /* the first unit, the one with a level of detail, whose coordinates stage_persp_lod forms, else -1 */
    int chain_fused_lanes;      /* the chain ends in a fused stage that samples every unit it reads, at the coordinates stage_persp forms: it may form them itself (SpanBuf.lanes) */
    uint8_t stencil_lut[4][256];        /* the chain's stencil tables (fragment_stencil_lut) */
    /* the chain's stencil cull (span_chain.c's run), set with those tables:
    ** on where a fragment failing the test keeps the stored value; the
    ** function, the masked reference and the value mask (8 bits) */
    struct { int on; unsigned int func; uint8_t ref, mask; } stencil_cull;
    uint8_t stencil_only[256];          /* span_stencil_only's: each stored value's new value */
    /* raster.c: the last flat colour packed for the framebuffer (format -1: none) */
    FRAGV flat_cache_color[4];
    int flat_cache_format;
    uint32_t flat_cache_packed;
    TexSpanSampler samplers[GLES_MAX_TEXTURE_UNITS];   /* each unit's, for the chain (texsample.c) */
    int sample_group[GLES_MAX_TEXTURE_UNITS];          /* its kernel's group (texture_span_sample_group) */
    int debug;
    int simd;                   /* SIMD_* the CPU runs (simd_detect) */

    /* per-draw scratch: transformed vertices and their stamps */
    Vertex *verts;
    uint32_t *vert_stamp;
    int64_t verts_capacity;
    uint32_t draw_stamp;

    /* {== the tail, which a worker's copy does not take per draw (raster.c's
    ** worker_prepare): tables fixed when the context is made (a worker
    ** takes them once, context.c's worker_create), and the flat colour's
    ** blend, a per-primitive cache each thread fills for itself. Kept after
    ** the fields the span stages read most, whose offsets they keep */
    FRAGV unorm8[256];          /* d / 255 as FRAGV: blending reads these */
    FRAGV unorm5[32], unorm6[64], unorm4[16], unorm1[2];   /* d / (2^bits - 1): 16-bit formats' channels */
    FRAGV texel_unorm8[256];    /* c / 255 */
    /* a flat colour's blend as a table per destination byte (span.c's
    ** span_flat_table) */
    FlatTable flat_table;
    /* the running threaded job's work and argument (raster_threaded),
    ** which its workers read until raster_join */
    void (*job_work)(GlesContext *ctx, void *arg);
    _Alignas(16) unsigned char job_arg[GLES_JOB_ARG_BYTES];
};

/* dirty bits */
#define DIRTY_MATRIX 1u
#define DIRTY_SPAN 2u
#define DIRTY_CLIP 4u
#define DIRTY_LIGHT 8u
#define DIRTY_TEXTURE 16u
#define DIRTY_ALL 0xffffffffu

/* whether the draws take the generic span path: the debug switch, or a
** sampling unit with a level-of-detail bias (EXT_texture_lod_bias) or an
** anisotropic texture (EXT_texture_filter_anisotropic): the vector
** samplers and fused stages compute an isotropic, unbiased lambda; or a
** unit sampling a cube map (texcube.c: the face is chosen per fragment) */
static inline int ctx_generic_spans(const GlesContext *ctx)
{
    if (ctx->debug & GLES_DEBUG_GENERIC_SPANS)
        return 1;
    for (int u = 0; u < GLES_MAX_TEXTURE_UNITS; u++)
        if (ctx->units[u].enabled && (ctx->units[u].lod_bias != 0.0 || ctx->units[u].bound->max_aniso > 1.0
                                      || ctx->units[u].enabled_cube))
            return 1;
    return 0;
}

/* KHR_debug's message of an error (debug.c): `where` the core function
** that records it, `why` the reason where the site gives one */
void debug_error(GlesContext *ctx, unsigned int err, const char *where, const char *why);

/* record an error: the first only stays for GetError, as the spec says;
** each raises a debug message while DEBUG_OUTPUT_KHR is on */
static inline void ctx_error_at(GlesContext *ctx, unsigned int err, const char *where, const char *why)
{
    if (ctx->error == GL_NO_ERROR)
        ctx->error = err;
    if (ctx->debug_output)
        debug_error(ctx, err, where, why);
}
#define ctx_error(ctx, err) ctx_error_at((ctx), (err), __func__, NULL)
#define ctx_error_why(ctx, err, why) ctx_error_at((ctx), (err), __func__, (why))

/* the instance of the span stages to run: the CPU's best, unless a
** debug switch asks for the baseline or at most AVX2 */
static inline int ctx_simd(const GlesContext *ctx)
{
    if (ctx->debug & GLES_DEBUG_BASELINE_SIMD)
        return SIMD_BASELINE;
    return (ctx->debug & GLES_DEBUG_AVX2_SIMD) && ctx->simd > SIMD_AVX2 ? SIMD_AVX2 : ctx->simd;
}

int ctx_message(GlesContext *ctx, int status, const char *fmt, ...);

/* may `add` bytes be allocated while `release` bytes held now are freed
** (the memory budget of textures and buffers) */
static inline int ctx_mem_fits(const GlesContext *ctx, int64_t add, int64_t release)
{
    return add <= release || add - release <= ctx->mem_limit - ctx->mem_used;
}
/* store an RGBA colour clamped to [0,1], as queried (d) and as computed (n) */
void ctx_set_clamped_color(double *d, NUM *n, const double *rgba);

#endif
