/*
** gles_core.h -- the core's whole public C API, the only header cffi parses.
** Every GL command takes the context first; there is no global state, so
** contexts in different threads never interact. Value arguments that the
** Common profile gives as floats arrive as double in every build: the x forms
** are converted exactly by the caller (x / 65536), and each build rounds the
** double once into its NUM type. The API state keeps the double, so queries
** return what the application set.
** Draw, clear and read commands return a status: 0, or a negative GLES_E*
** code for Python-level misuse (the message is in gles_last_message).
** Keep this file free of preprocessor logic: cffi parses it as it is.
*/
#ifndef GLES_CORE_H
#define GLES_CORE_H

#include <stdint.h>

typedef struct GlesContext GlesContext;

/* status codes of the commands that return one */
#define GLES_OK 0
#define GLES_EVALUE -1   /* array or buffer too short, index out of range */
#define GLES_EMEMORY -2  /* allocation failed (also sets OUT_OF_MEMORY) */
#define GLES_RANGE 1     /* the draw broke the overflow rule (gles_range_last) */

/* framebuffer colour formats */
#define GLES_COLOR_RGBA8888 0  /* uint32, R in the low byte */
#define GLES_COLOR_RGB565 1    /* uint16 as GL's packed types: R in the high bits */
#define GLES_COLOR_RGBA4444 2  /* uint16: R 15-12, G 11-8, B 7-4, A 3-0 */
#define GLES_COLOR_RGBA5551 3  /* uint16: R 15-11, G 10-6, B 5-1, A 0 */

/* profiles */
#define GLES_PROFILE_COMMON 0
#define GLES_PROFILE_COMMON_LITE 1

/* kinds of values returned by gles_get (the caller applies the spec's
** conversion rules for each Get command from the kind) */
#define GLES_KIND_INT 1     /* integers: sizes, counts, names */
#define GLES_KIND_ENUM 2    /* enums: never scaled */
#define GLES_KIND_BOOL 3    /* booleans */
#define GLES_KIND_FLOAT 4   /* plain real values */
#define GLES_KIND_NORM 5    /* colours, depth values, normals: [-1,1] maps
                               to the whole integer range in GetIntegerv */

/* {====================================================================
** context */
const char *gles_numeric_name(void);
GlesContext *gles_context_create(int width, int height, int color_format,
                                 int depth_bits, int stencil_bits, int profile);
void gles_context_destroy(GlesContext *ctx);
#define GLES_MAX_THREADS 64
/* rasterize draws on `threads` threads (1..GLES_MAX_THREADS; the caller
** and threads - 1 workers the context keeps), each on its own rows, so the
** bytes are those of one thread; returns the number in use, which is 1
** where threads are not built in or cannot be started */
int gles_threads_set(GlesContext *ctx, int threads);
int gles_threads(GlesContext *ctx);
const char *gles_last_message(GlesContext *ctx);
void *gles_color_buffer(GlesContext *ctx);     /* bottom row first */
void *gles_depth_buffer(GlesContext *ctx);     /* uint32 per pixel */
void *gles_stencil_buffer(GlesContext *ctx);   /* uint8 per pixel */
/* the budget of texture images and buffer data together, in bytes (the
** default is 256 MiB): an allocation past it is OUT_OF_MEMORY and changes
** nothing; a limit below the current use only stops further growth */
void gles_memory_limit(GlesContext *ctx, int64_t limit);
int64_t gles_memory_used(GlesContext *ctx);
int gles_width(GlesContext *ctx);
int gles_height(GlesContext *ctx);
/* debug switches for tests: 1 forces the generic span path; 2 and 4 break
** the rasterizer on purpose (flip the fill rule's tie, drop the last pixel of
** every span) so that tests can show the suite catches it; 8 runs the
** vertex stage per vertex (the reference of the batched path); 16 runs the
** baseline span stages where the CPU has a vector instance (simd.h); 32
** caps them at AVX2; 64 shares every draw's vertex work and rasterization
** among the context's threads, however small the draw */
void gles_debug_set(GlesContext *ctx, int flags);
/* name of the span function the last triangle used (for path tests) */
const char *gles_last_span_name(GlesContext *ctx);
/* the instruction set the span stages run with: "avx512" (the double
** build's bilinear kernel; the rest as "avx2"), "avx2" or "baseline" */
const char *gles_simd_name(GlesContext *ctx);
/* for tests: the texels unit's span sampler gives for n fragments (at
** most 4096) at coords (s, t, then the right and upper neighbours' s, t,
** six doubles a fragment), as FRAGV values in double (0.30 integers in the
** fixed build), through the best instance the CPU has up to level simd
** (0 baseline, 1 AVX2, 2 AVX-512); 0 when the unit samples no complete
** texture */
int gles_debug_sample(GlesContext *ctx, int unit, int simd, int n, const double *coords, double *out);
/* for tests, fixed build (0 elsewhere): the perspective weights (wgt_persp)
** of n points with edge values e[3 j .. 3 j + 2] for a triangle of the given
** 1/w mantissas (below 2^30, as recipw_of makes) and shifts (lin_recip is
** the triangle's, for an affine one), into out[3 j ..], four at a time by
** the vector kernel where simd != 0 and the CPU has one, else one by one */
int gles_debug_persp(int simd, int eshift, int64_t lin_recip, const int64_t mant[3], const int qshift[3], int affine,
                     int n, const int64_t *e, int32_t *out);
/* for tests, fixed build (0 elsewhere): as gles_debug_persp, each point's
** weights and their tangents (wgt_tangent) along the edge steps ea and eb
** of a triangle of twice the area area2, nine values a point in out */
int gles_debug_persp_tangent(int simd, int eshift, int64_t lin_recip, const int64_t mant[3], const int qshift[3],
                             int affine, int64_t area2, const int64_t ea[3], const int64_t eb[3], int n,
                             const int64_t *e, int32_t *out);
/* the most pixels of a row the span chain takes through its stages at
** once (a chunk; tests size rows past it) */
int gles_span_chunk(void);
/* for tests, fixed build (0 elsewhere): stage_persp over one chunk of n
** (at most gles_span_chunk()) neighbouring pixels whose edge values are e0 + j ea (slot
** j), for a triangle set up as gles_debug_persp's, by the chain's vector
** instance where simd != 0 and the CPU has one, else its baseline */
int gles_debug_persp_chunk(int simd, int eshift, int64_t lin_recip, const int64_t mant[3], const int qshift[3],
                           int affine, int n, const int64_t e0[3], const int64_t ea[3], int32_t *out);
/* for tests, fixed build (0 elsewhere): the colour stage's value of n
** fragments with weights p[3 j .. 3 j + 2] for vertex colours col[4 k ..
** 4 k + 3] (0.30), clamped to [0, 1] when clamp (as for texturing), into
** out[4 j ..]: by the vector kernels where simd != 0 and the CPU has them
** (the colours in int32 range, else the scalar code, as the stage does) */
int gles_debug_color(int simd, int clamp, const int64_t col[12], int n, const int32_t *p, int64_t *out);
/* for tests, float build with AVX2 (-1 elsewhere): the float build's
** fused stage's kernel (f8_modwrite_run) over n fragments (at most
** gles_span_chunk(), padded to a whole group as the stage pads) at offsets
** k (ascending) of the RGBA8888 words dst: vertex colours col[4 i ..] at
** weights p[3 j ..] (smooth) or the flat colour col[0..3], texels
** ct[4 j ..], as gles_debug_modulate_write; returns 0 when run */
int gles_debug_modulate_write_f(int smooth, int rgb, int kind, unsigned int alpha_func, uint32_t alpha_ref,
                                const float col[12], int n, const uint8_t *k, const float *p, const float *ct,
                                uint32_t *dst);
/* for tests, double build with AVX2 (-1 elsewhere): the kernel of
** stage_modulate_write_proved (the double build's AVX2 instance: float
** lanes, each byte proved or taken from the exact chain) over n fragments
** (at most gles_span_chunk(), padded to a whole group as the stage pads)
** at offsets k (ascending) of the words dst, with the arguments of
** gles_debug_modulate_write_f as doubles (vertex colours in [0, 1]), and
** dot3 (with the first unit's texels ct0), rgb565, dither and x0 as
** gles_debug_modulate_write has them; returns the fragments the float
** lanes left to the exact code */
int gles_debug_modulate_write_d(int smooth, int rgb, int kind, unsigned int alpha_func, uint32_t alpha_ref,
                                const double col[12], int n, const uint8_t *k, const double *p, int dot3,
                                const double *ct0, const double *ct, int rgb565, int dither, int x0, void *dst);
/* for tests, fixed build with AVX2 (-1 elsewhere): stage_modulate_write's
** kernel over n fragments (at most gles_span_chunk()) at offsets k
** (ascending) of the words dst: vertex colours col[4 i ..] (0.30, in
** [0, 1]) at weights p[3 j ..] (smooth), or the flat colour col[0..3];
** texels ct[4 j ..] (0.30) of an RGBA (or, rgb != 0, RGB) texture under
** MODULATE; the alpha test
** (alpha_func, GL_ALWAYS for none, against the 8-bit alpha_ref) and blend
** kind 0 (none), 1 (SRC_ALPHA, ONE_MINUS_SRC_ALPHA) or 2 (ONE, ONE, not on
** RGB565). dst holds uint32_t RGBA8888 words, or (rgb565 != 0) uint16_t
** RGB565 words whose first is column x0, dithered when dither != 0. With
** pad != 0 a tail of fewer than eight fragments is padded to a group as
** the stage that samples in the kernel pads it. With dot3 = 1 (DOT3_RGB,
** MODULATE alpha) or 2 (DOT3_RGBA) the colour first goes through a first
** unit's COMBINE DOT3 with its texels ct0[4 j ..] (0.30, scales 1), as
** stage_dot3_write runs it; ct0 is not read with dot3 = 0. Returns the
** fragments the float lanes left to the exact code, or -1 when not run. */
int gles_debug_modulate_write(int smooth, int rgb, int kind, unsigned int alpha_func, uint32_t alpha_ref,
                              const int64_t col[12], int n, const uint8_t *k, const int32_t *p, int dot3,
                              const int64_t *ct0, const int64_t *ct, int pad, int rgb565, int dither, int x0,
                              void *dst);
/* for tests, fixed build with AVX2 (-1 elsewhere): the fused sampling, fog
** and write of a lone REPLACE unit (avx2_fog_write_texels8) over one group
** of eight fragments: fragment i's bilinear texels c00, c10, c01, c11 at
** tex1[4 i ..] (RGBA8888 words) with the weights ab[2 i] along s and
** ab[2 i + 1] along t (0..65535), and with two != 0 mixed by frac[i]
** (0.30, below 1) with those of tex2 at the same weights; its weights w[3 i
** ..] (0.30), the vertices' fog factors fog[0..2] (16.16, within [-2, 2])
** and the fog colour fc[0..2] (0.30, in [0, 1]); an RGBA8888 word, or
** (rgb565 != 0) an RGB565 pixel of column i (dithered by t_row[i & 3],
** 0.30, where dither != 0), into out[i] where the kernel proves it.
** Returns the proved fragments as bits (bit i: out[i] written), -1 when
** not run (or an argument out of its range) */
int gles_debug_fog_write_texels(const uint32_t tex1[32], const uint32_t tex2[32], const int32_t ab[16], int two,
                                const int64_t frac[8], const int32_t w[24], const int32_t fog[3],
                                const int64_t fc[3], int rgb565, int dither, const int64_t t_row[4],
                                uint32_t out[8]);
/* for tests, fixed build (0 elsewhere): a lane kernel of the vertex batch
** over n lanes (a multiple of 8, at most 64), through the AVX2 kernel where
** simd != 0 and the CPU has AVX2, else the scalar code; returns 1 when run.
**   0: num_dot4_lanes: out[i] = m[0] x + m[1] y + m[2] z + m[3] w rounded
**      once, rows x, y, z, w at in[0], in[64], in[128], in[192]; m[4] is
**      w_one (the w term is then m[3] * 1)
**   1: num_dot3_lanes: m[0..2], rows x, y, z as above
**   2: the FLOAT array fetch: in holds the bits of n vertices of m[0]
**      (1..4) floats, m[1] (>= m[0]) floats apart; lane i reads vertex
**      n - 1 - i when m[2], else vertex i; component c into out[64 c + i]
**   3: a directional light's term (red channel): lanes of n . VP at in[0],
**      the colour at in[64], the accumulator at in[128], n . h at in[192];
**      material x light products ambient m[0], diffuse m[1], specular m[6];
**      the light's ambient and diffuse m[2], m[3] (COLOR_MATERIAL, when
**      m[9], multiplies them by the colour); scale m[4], shininess m[5];
**      m[7]: the light is specular. out = the accumulator plus the term,
**      as light_side adds it
**   4: the range check's largest |component| (range.c) of vertices m[2] to
**      m[3] (< n) of a FLOAT array of m[0] floats m[1] apart at in, as a
**      float into out[0] (exact: the result is a float's value or inf)
**   5: num_normalize3 of the lanes' vectors (rows x, y, z at in[0],
**      in[64], in[128]) into out[0], out[64], out[128]
**   8: num_pow of the lanes in[0..n) with the exponent m[0] (16.16) into
**      out[0..n)
**   9: fx_exp2 of int64 lanes (0.30, |y| < 2^62; lane i's low and high
**      words at in[2 i], in[2 i + 1], n <= 64) into out[0..n)
** m holds 10 values, out 256, in 256 (kernels 2 and 4: n m[1] floats). */
int gles_debug_vertex_lanes(int simd, int kernel, int n, const int32_t *m, const int32_t *in, int32_t *out);

/* the numeric layer, for tests: converts a and b to NUM (exact for
** multiples of 2^-16 in the fixed build), applies op, returns the result
** as double; ops are GLES_NUMOP_* */
#define GLES_NUMOP_FROM 0
#define GLES_NUMOP_ADD 1
#define GLES_NUMOP_SUB 2
#define GLES_NUMOP_MUL 3
#define GLES_NUMOP_DIV 4
#define GLES_NUMOP_RECIP 5
#define GLES_NUMOP_SQRT 6
#define GLES_NUMOP_RSQRT 7
#define GLES_NUMOP_SIN_DEG 8
#define GLES_NUMOP_COS_DEG 9
#define GLES_NUMOP_TO_UNORM8 10
#define GLES_NUMOP_FROM_UNORM8 11
#define GLES_NUMOP_POW01 12
double gles_num_eval(int op, double a, double b);

/* the per-draw overflow rule c*s + t < 16384 (range.c): off, checked (the
** draw goes on and returns GLES_RANGE), or checked with the draw skipped */
#define GLES_RANGE_OFF 0
#define GLES_RANGE_CHECK 1
#define GLES_RANGE_SKIP 2
void gles_range_set(GlesContext *ctx, int mode);
/* the last violation: c, s, t and c*s + t of the rule (c*s + t < 16384
** when only arrays overflowed), and per array (vertex, normal, colour,
** point size, matrix index, weight, texture coordinates of unit 0..3) the
** largest drawn |value| of a FLOAT array that 16.16 cannot hold, else 0;
** returns the bit mask of those arrays */
#define GLES_RANGE_ARRAYS 10
int gles_range_last(GlesContext *ctx, double out[4], double array_max[10]);
/* draws checked and draws that broke the rule */
void gles_range_counts(GlesContext *ctx, int64_t out[2]);
void gles_range_reset(GlesContext *ctx);

/* {====================================================================
** state queries: up to 16 values into out; returns the count, 0 for an
** unknown pname (INVALID_ENUM is set); *kind receives a GLES_KIND_* */
int gles_get(GlesContext *ctx, unsigned int pname, double *out, int *kind);
unsigned int gles_GetError(GlesContext *ctx);
unsigned char gles_IsEnabled(GlesContext *ctx, unsigned int cap);
void gles_set_error(GlesContext *ctx, unsigned int err);

/* {====================================================================
** simple state */
void gles_Enable(GlesContext *ctx, unsigned int cap);
void gles_Disable(GlesContext *ctx, unsigned int cap);
void gles_EnableClientState(GlesContext *ctx, unsigned int array);
void gles_DisableClientState(GlesContext *ctx, unsigned int array);
void gles_Viewport(GlesContext *ctx, int x, int y, int width, int height);
void gles_Scissor(GlesContext *ctx, int x, int y, int width, int height);
void gles_DepthRange(GlesContext *ctx, double n, double f);
void gles_ClearColor(GlesContext *ctx, double r, double g, double b, double a);
void gles_ClearDepth(GlesContext *ctx, double d);
void gles_ClearStencil(GlesContext *ctx, int s);
void gles_ColorMask(GlesContext *ctx, unsigned char r, unsigned char g, unsigned char b, unsigned char a);
void gles_DepthMask(GlesContext *ctx, unsigned char flag);
void gles_DepthFunc(GlesContext *ctx, unsigned int func);
void gles_CullFace(GlesContext *ctx, unsigned int mode);
void gles_FrontFace(GlesContext *ctx, unsigned int mode);
void gles_ShadeModel(GlesContext *ctx, unsigned int mode);
void gles_Hint(GlesContext *ctx, unsigned int target, unsigned int mode);
void gles_PixelStorei(GlesContext *ctx, unsigned int pname, int param);
void gles_ActiveTexture(GlesContext *ctx, unsigned int texture);
void gles_ClientActiveTexture(GlesContext *ctx, unsigned int texture);

/* {====================================================================
** matrices (m is 16 values, column-major) */
void gles_MatrixMode(GlesContext *ctx, unsigned int mode);
void gles_LoadIdentity(GlesContext *ctx);
void gles_LoadMatrix(GlesContext *ctx, const double *m);
void gles_MultMatrix(GlesContext *ctx, const double *m);
void gles_PushMatrix(GlesContext *ctx);
void gles_PopMatrix(GlesContext *ctx);
void gles_Translate(GlesContext *ctx, double x, double y, double z);
void gles_Scale(GlesContext *ctx, double x, double y, double z);
void gles_Rotate(GlesContext *ctx, double angle, double x, double y, double z);
void gles_Frustum(GlesContext *ctx, double l, double r, double b, double t, double n, double f);
void gles_Ortho(GlesContext *ctx, double l, double r, double b, double t, double n, double f);
void gles_ClipPlane(GlesContext *ctx, unsigned int plane, const double *eq);
/* OES_matrix_palette */
void gles_CurrentPaletteMatrixOES(GlesContext *ctx, unsigned int index);
void gles_LoadPaletteFromModelViewMatrixOES(GlesContext *ctx);
int gles_MatrixIndexPointerOES(GlesContext *ctx, int size, unsigned int type, int stride, const void *ptr, int64_t nbytes);
int gles_WeightPointerOES(GlesContext *ctx, int size, unsigned int type, int stride, const void *ptr, int64_t nbytes);
void gles_GetClipPlane(GlesContext *ctx, unsigned int plane, double *eq);

/* {====================================================================
** lighting (§2.12): params holds 1 or 4 values as the pname needs; `vector`
** is 0 for the scalar forms (Lightf...), which accept scalar pnames only.
** The getters fill out (up to 4) and return the count (0 on a GL error). */
void gles_Light(GlesContext *ctx, unsigned int light, unsigned int pname, const double *params, int vector);
void gles_LightModel(GlesContext *ctx, unsigned int pname, const double *params, int vector);
void gles_Material(GlesContext *ctx, unsigned int face, unsigned int pname, const double *params, int vector);
int gles_GetLight(GlesContext *ctx, unsigned int light, unsigned int pname, double *out);
int gles_GetMaterial(GlesContext *ctx, unsigned int face, unsigned int pname, double *out);

/* {====================================================================
** per-fragment operations and fog (§4.1, §3.8); Fog's params as Light's */
void gles_AlphaFunc(GlesContext *ctx, unsigned int func, double ref);
void gles_StencilFunc(GlesContext *ctx, unsigned int func, int ref, unsigned int mask);
void gles_StencilOp(GlesContext *ctx, unsigned int fail, unsigned int zfail, unsigned int zpass);
void gles_StencilMask(GlesContext *ctx, unsigned int mask);
void gles_BlendFunc(GlesContext *ctx, unsigned int src, unsigned int dst);
void gles_BlendFuncSeparateOES(GlesContext *ctx, unsigned int src_rgb, unsigned int dst_rgb,
                               unsigned int src_alpha, unsigned int dst_alpha);
void gles_BlendEquationOES(GlesContext *ctx, unsigned int mode);
void gles_BlendEquationSeparateOES(GlesContext *ctx, unsigned int rgb, unsigned int alpha);
void gles_LogicOp(GlesContext *ctx, unsigned int op);
void gles_SampleCoverage(GlesContext *ctx, double value, unsigned char invert);
void gles_Fog(GlesContext *ctx, unsigned int pname, const double *params, int vector);

/* {====================================================================
** textures (§3.7): TexParameter/TexEnv params as Light's; getters fill out
** (up to 4) and return the count; nbytes as for client arrays */
void gles_GenTextures(GlesContext *ctx, int n, unsigned int *names);
void gles_DeleteTextures(GlesContext *ctx, int n, const unsigned int *names);
void gles_BindTexture(GlesContext *ctx, unsigned int target, unsigned int name);
unsigned char gles_IsTexture(GlesContext *ctx, unsigned int name);
int gles_TexImage2D(GlesContext *ctx, unsigned int target, int level, int internalformat, int width, int height,
                    int border, unsigned int format, unsigned int type, const void *pixels, int64_t nbytes);
int gles_TexSubImage2D(GlesContext *ctx, unsigned int target, int level, int xoffset, int yoffset, int width,
                       int height, unsigned int format, unsigned int type, const void *pixels, int64_t nbytes);
void gles_CopyTexImage2D(GlesContext *ctx, unsigned int target, int level, unsigned int internalformat, int x, int y,
                         int width, int height, int border);
void gles_CopyTexSubImage2D(GlesContext *ctx, unsigned int target, int level, int xoffset, int yoffset, int x, int y,
                            int width, int height);
int gles_CompressedTexImage2D(GlesContext *ctx, unsigned int target, int level, unsigned int internalformat,
                              int width, int height, int border, int image_size, const void *data, int64_t nbytes);
void gles_CompressedTexSubImage2D(GlesContext *ctx, unsigned int target, int level, int xoffset, int yoffset,
                                  int width, int height, unsigned int format, int image_size, const void *data);
void gles_TexParameter(GlesContext *ctx, unsigned int target, unsigned int pname, const double *params, int vector);
int gles_GetTexParameter(GlesContext *ctx, unsigned int target, unsigned int pname, double *out);
void gles_TexEnv(GlesContext *ctx, unsigned int target, unsigned int pname, const double *params, int vector);
int gles_GetTexEnv(GlesContext *ctx, unsigned int target, unsigned int pname, double *out);
/* OES_texture_cube_map: TexGen*OES (coord TEXTURE_GEN_STR_OES, pname
** TEXTURE_GEN_MODE_OES) and GetTexGen*OES, params as TexEnv's */
void gles_TexGen(GlesContext *ctx, unsigned int coord, unsigned int pname, const double *params, int vector);
int gles_GetTexGen(GlesContext *ctx, unsigned int coord, unsigned int pname, double *out);
/* bytes a TexImage2D with these arguments reads (UNPACK_ALIGNMENT applied),
** and the size of a paletted image of `levels` levels (-1: not paletted) */
int64_t texture_image_bytes(const GlesContext *ctx, int width, int height, unsigned int format, unsigned int type);
int64_t texture_paletted_bytes(unsigned int internalformat, int levels, int width, int height);

/* {====================================================================
** points, lines and polygon offset (§3.3-3.5); PointParameter's params as
** Light's */
void gles_PointSize(GlesContext *ctx, double size);
void gles_LineWidth(GlesContext *ctx, double width);
void gles_PointParameter(GlesContext *ctx, unsigned int pname, const double *params, int vector);
void gles_PolygonOffset(GlesContext *ctx, double factor, double units);
/* OES_draw_texture: every form arrives as doubles */
void gles_DrawTexOES(GlesContext *ctx, double x, double y, double z, double width, double height);

/* {====================================================================
** current values */
void gles_Color4(GlesContext *ctx, double r, double g, double b, double a);
void gles_Normal3(GlesContext *ctx, double x, double y, double z);
void gles_MultiTexCoord4(GlesContext *ctx, unsigned int target, double s, double t, double r, double q);

/* {====================================================================
** vertex arrays and buffer objects; nbytes is the length of a client
** array (-1 when unknown), ignored while a buffer object is bound; the
** pointer commands return 1 when the array was set, 0 on a GL error */
int gles_VertexPointer(GlesContext *ctx, int size, unsigned int type, int stride, const void *ptr, int64_t nbytes);
int gles_ColorPointer(GlesContext *ctx, int size, unsigned int type, int stride, const void *ptr, int64_t nbytes);
int gles_NormalPointer(GlesContext *ctx, unsigned int type, int stride, const void *ptr, int64_t nbytes);
int gles_TexCoordPointer(GlesContext *ctx, int size, unsigned int type, int stride, const void *ptr, int64_t nbytes);
int gles_PointSizePointerOES(GlesContext *ctx, unsigned int type, int stride, const void *ptr, int64_t nbytes);
/* the pointer (or offset) last given for an array, for GetPointerv */
uintptr_t gles_GetPointer(GlesContext *ctx, unsigned int pname);
void gles_GenBuffers(GlesContext *ctx, int n, unsigned int *names);
void gles_DeleteBuffers(GlesContext *ctx, int n, const unsigned int *names);
void gles_BindBuffer(GlesContext *ctx, unsigned int target, unsigned int buffer);
int gles_BufferData(GlesContext *ctx, unsigned int target, int64_t size, const void *data, unsigned int usage);
void gles_BufferSubData(GlesContext *ctx, unsigned int target, int64_t offset, int64_t size, const void *data);
unsigned char gles_IsBuffer(GlesContext *ctx, unsigned int buffer);
/* OES_mapbuffer and EXT_map_buffer_range: the mapping's address, NULL on
** a GL error */
void *gles_MapBufferOES(GlesContext *ctx, unsigned int target, unsigned int access);
void *gles_MapBufferRangeEXT(GlesContext *ctx, unsigned int target, int64_t offset, int64_t length,
                             unsigned int access);
void gles_FlushMappedBufferRangeEXT(GlesContext *ctx, unsigned int target, int64_t offset, int64_t length);
unsigned char gles_UnmapBufferOES(GlesContext *ctx, unsigned int target);
/* BUFFER_MAP_POINTER_OES into *out (NULL when unmapped); 0 on a GL error */
int gles_GetBufferPointervOES(GlesContext *ctx, unsigned int target, unsigned int pname, void **out);
/* the Python layer's writes into a mapping (its numpy copy of the mapped
** range, copied in at a flush or unmap): `offset` from the buffer's start,
** within the mapped range of a write mapping; GLES_EVALUE otherwise, no GL
** error (not a GL command) */
int gles_buffer_map_write(GlesContext *ctx, unsigned int target, int64_t offset, const void *data, int64_t nbytes);
/* the size of the framebuffer drawn into and read (the window's, or the
** bound framebuffer object's when it is complete) */
void gles_draw_size(GlesContext *ctx, int *wh);
/* OES_framebuffer_object (fbo.c) */
void gles_GenFramebuffersOES(GlesContext *ctx, int n, unsigned int *names);
void gles_GenRenderbuffersOES(GlesContext *ctx, int n, unsigned int *names);
void gles_BindFramebufferOES(GlesContext *ctx, unsigned int target, unsigned int name);
void gles_BindRenderbufferOES(GlesContext *ctx, unsigned int target, unsigned int name);
void gles_DeleteFramebuffersOES(GlesContext *ctx, int n, const unsigned int *names);
void gles_DeleteRenderbuffersOES(GlesContext *ctx, int n, const unsigned int *names);
unsigned char gles_IsFramebufferOES(GlesContext *ctx, unsigned int name);
unsigned char gles_IsRenderbufferOES(GlesContext *ctx, unsigned int name);
void gles_RenderbufferStorageOES(GlesContext *ctx, unsigned int target, unsigned int internalformat, int width,
                                 int height);
void gles_FramebufferTexture2DOES(GlesContext *ctx, unsigned int target, unsigned int attachment,
                                  unsigned int textarget, unsigned int texture, int level);
void gles_FramebufferRenderbufferOES(GlesContext *ctx, unsigned int target, unsigned int attachment,
                                     unsigned int renderbuffertarget, unsigned int renderbuffer);
unsigned int gles_CheckFramebufferStatusOES(GlesContext *ctx, unsigned int target);
/* one value into params[0]; 0 on a GL error */
int gles_GetFramebufferAttachmentParameterivOES(GlesContext *ctx, unsigned int target, unsigned int attachment,
                                                 unsigned int pname, int *params);
int gles_GetRenderbufferParameterivOES(GlesContext *ctx, unsigned int target, unsigned int pname, int *params);
void gles_GenerateMipmapOES(GlesContext *ctx, unsigned int target);
/* EXT_discard_framebuffer */
void gles_DiscardFramebufferEXT(GlesContext *ctx, unsigned int target, int n, const unsigned int *attachments);
/* OES_vertex_array_object */
void gles_GenVertexArraysOES(GlesContext *ctx, int n, unsigned int *names);
void gles_DeleteVertexArraysOES(GlesContext *ctx, int n, const unsigned int *names);
void gles_BindVertexArrayOES(GlesContext *ctx, unsigned int name);
unsigned char gles_IsVertexArrayOES(GlesContext *ctx, unsigned int name);
void gles_GetBufferParameteriv(GlesContext *ctx, unsigned int target, unsigned int pname, int *params);

/* {====================================================================
** KHR_debug (debug.c). String arguments arrive as `const void *` with the
** bytes readable there (nbytes, -1 unknown) and return a status like the
** client arrays' (GLES_EVALUE when a length reaches past the data, or no
** terminator lies within it). ES 1.1 has no sync objects, so the Ptr label
** commands take no pointer: none could name one (INVALID_VALUE). */
#define GLES_DEBUG_MAX_MESSAGE_LENGTH 1024   /* MAX_DEBUG_MESSAGE_LENGTH_KHR */
#define GLES_DEBUG_MAX_LABEL_LENGTH 256      /* MAX_LABEL_LENGTH_KHR */
typedef void (*GlesDebugProc)(unsigned int source, unsigned int type, unsigned int id, unsigned int severity,
                              int length, const char *message, const void *user_param);
/* a debug context (on) starts with DEBUG_OUTPUT_KHR enabled: set it so */
void gles_debug_context_set(GlesContext *ctx, int on);
void gles_DebugMessageControlKHR(GlesContext *ctx, unsigned int source, unsigned int type, unsigned int severity,
                                 int n, const unsigned int *ids, unsigned char enabled);
int gles_DebugMessageInsertKHR(GlesContext *ctx, unsigned int source, unsigned int type, unsigned int id,
                               unsigned int severity, int length, const void *buf, int64_t nbytes);
/* the application's callback (C ABI), called on the calling thread */
void gles_DebugMessageCallbackKHR(GlesContext *ctx, GlesDebugProc callback, const void *user_param);
unsigned int gles_GetDebugMessageLogKHR(GlesContext *ctx, unsigned int count, int buf_size, unsigned int *sources,
                                        unsigned int *types, unsigned int *ids, unsigned int *severities,
                                        int *lengths, char *message_log);
int gles_PushDebugGroupKHR(GlesContext *ctx, unsigned int source, unsigned int id, int length, const void *message,
                           int64_t nbytes);
void gles_PopDebugGroupKHR(GlesContext *ctx);
int gles_ObjectLabelKHR(GlesContext *ctx, unsigned int identifier, unsigned int name, int length, const void *label,
                        int64_t nbytes);
/* 1 with the label written, 0 on a GL error */
int gles_GetObjectLabelKHR(GlesContext *ctx, unsigned int identifier, unsigned int name, int buf_size, int *length,
                           char *label);
int gles_ObjectPtrLabelKHR(GlesContext *ctx, int length, const void *label, int64_t nbytes);
int gles_GetObjectPtrLabelKHR(GlesContext *ctx, int buf_size, int *length, char *label);
/* the Python binding's callback: with on, the messages a callback would
** receive wait in a queue (up to 4096) instead, which gles_debug_take
** empties as GetDebugMessageLogKHR empties the log, with no GL error;
** gles_debug_queued is the next one's length, terminator included (0: none) */
void gles_debug_queue_set(GlesContext *ctx, int on);
int gles_debug_queued(GlesContext *ctx);
unsigned int gles_debug_take(GlesContext *ctx, unsigned int count, int buf_size, unsigned int *sources,
                             unsigned int *types, unsigned int *ids, unsigned int *severities, int *lengths,
                             char *message_log);

/* {====================================================================
** drawing and pixels */
int gles_DrawArrays(GlesContext *ctx, unsigned int mode, int first, int count);
int gles_DrawElements(GlesContext *ctx, unsigned int mode, int count, unsigned int type,
                      const void *indices, int64_t nbytes);
int gles_Clear(GlesContext *ctx, unsigned int mask);
int gles_ReadPixels(GlesContext *ctx, int x, int y, int width, int height,
                    unsigned int format, unsigned int type, void *out, int64_t nbytes);
void gles_Finish(GlesContext *ctx);
void gles_Flush(GlesContext *ctx);

#endif
