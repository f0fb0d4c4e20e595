/*
** array.c -- vertex arrays and buffer objects (ES 1.1 §2.8, §2.9).
** Owns: the array pointers and their validation (Table 2.4), buffer object
**       storage, the GL-name table, and conversion of one array element to
**       NUM (Table 2.7 for normalised types).
** Never does: transformation (vertex.c) or deciding which vertices to read.
*/
#include <stdlib.h>
#include <string.h>
#include "array.h"
#include "debug.h"

/* {====================================================================
** name table: open addressing, linear probing */

#define NAME_EMPTY 0u
#define NAME_DELETED (~0u)

void names_init(NameTable *t)
{
    memset(t, 0, sizeof *t);
    t->next_name = 1;
}

void names_free(NameTable *t)
{
    free(t->keys);
    free(t->values);
    memset(t, 0, sizeof *t);
}

static uint32_t name_hash(unsigned int name) { return name * 2654435761u; }

void *names_lookup(const NameTable *t, unsigned int name)
{
    if (!t->capacity || name == NAME_EMPTY || name == NAME_DELETED)
        return NULL;
    uint32_t mask = t->capacity - 1;
    for (uint32_t i = name_hash(name) & mask;; i = (i + 1) & mask) {
        if (t->keys[i] == name)
            return t->values[i];
        if (t->keys[i] == NAME_EMPTY)
            return NULL;
    }
}

static int names_grow(NameTable *t)
{
    uint32_t cap = t->capacity ? t->capacity * 2 : 64;
    unsigned int *keys = calloc(cap, sizeof *keys);
    void **values = calloc(cap, sizeof *values);
    if (!keys || !values) {
        free(keys);
        free(values);
        return 0;
    }
    uint32_t used = 0;
    for (uint32_t i = 0; i < t->capacity; i++) {
        unsigned int k = t->keys[i];
        if (k == NAME_EMPTY || k == NAME_DELETED)
            continue;
        uint32_t j = name_hash(k) & (cap - 1);
        while (keys[j] != NAME_EMPTY)
            j = (j + 1) & (cap - 1);
        keys[j] = k;
        values[j] = t->values[i];
        used++;
    }
    free(t->keys);
    free(t->values);
    t->keys = keys;
    t->values = values;
    t->capacity = cap;
    t->used = used;
    return 1;
}

int names_insert(NameTable *t, unsigned int name, void *value)
{
    if (name == NAME_EMPTY || name == NAME_DELETED)
        return 0;
    if ((t->used + 1) * 4 >= t->capacity * 3 && !names_grow(t))
        return 0;
    uint32_t mask = t->capacity - 1;
    uint32_t slot = UINT32_MAX;
    for (uint32_t i = name_hash(name) & mask;; i = (i + 1) & mask) {
        if (t->keys[i] == name) {
            t->values[i] = value;
            return 1;
        }
        if (t->keys[i] == NAME_DELETED && slot == UINT32_MAX)
            slot = i;
        if (t->keys[i] == NAME_EMPTY) {
            if (slot == UINT32_MAX) {
                slot = i;
                t->used++;
            }
            break;
        }
    }
    t->keys[slot] = name;
    t->values[slot] = value;
    return 1;
}

void *names_remove(NameTable *t, unsigned int name)
{
    if (!t->capacity || name == NAME_EMPTY || name == NAME_DELETED)
        return NULL;
    uint32_t mask = t->capacity - 1;
    for (uint32_t i = name_hash(name) & mask;; i = (i + 1) & mask) {
        if (t->keys[i] == name) {
            void *v = t->values[i];
            t->keys[i] = NAME_DELETED;
            t->values[i] = NULL;
            return v;
        }
        if (t->keys[i] == NAME_EMPTY)
            return NULL;
    }
}

void names_generate(NameTable *t, int n, unsigned int *out)
{
    for (int i = 0; i < n; i++) {
        while (t->next_name == NAME_EMPTY || t->next_name == NAME_DELETED || names_lookup(t, t->next_name))
            t->next_name++;
        out[i] = t->next_name++;
    }
}

/* {====================================================================
** array state */

static const unsigned int array_caps[ARR_TEXCOORD0] = {
    GL_VERTEX_ARRAY, GL_NORMAL_ARRAY, GL_COLOR_ARRAY, GL_POINT_SIZE_ARRAY_OES,
    GL_MATRIX_INDEX_ARRAY_OES, GL_WEIGHT_ARRAY_OES,
};

/* Table 6.4's initial array state */
static void arrays_default(const GlesContext *ctx, ArrayState arrays[ARR_COUNT])
{
    for (int i = 0; i < ARR_COUNT; i++) {
        ArrayState *a = &arrays[i];
        memset(a, 0, sizeof *a);
        a->size = 4;
        /* Table 6.4: FLOAT, or FIXED where FLOAT does not exist (Common-Lite) */
        a->type = ctx->profile == GLES_PROFILE_COMMON_LITE ? GL_FIXED : GL_FLOAT;
        a->nbytes = -1;
    }
    arrays[ARR_NORMAL].size = 3;
    arrays[ARR_POINT_SIZE].size = 1;
    /* OES_matrix_palette: size 0, UNSIGNED_BYTE indices, FLOAT weights */
    arrays[ARR_MATRIX_INDEX].size = 0;
    arrays[ARR_MATRIX_INDEX].type = GL_UNSIGNED_BYTE;
    arrays[ARR_WEIGHT].size = 0;
}

void array_init(GlesContext *ctx)
{
    names_init(&ctx->buffers);
    names_init(&ctx->vaos);
    ctx->vao = NULL;
    arrays_default(ctx, ctx->arrays);
}

static void buffer_free(GlesContext *ctx, BufferObject *b)
{
    if (b) {
        if (b->data)
            ctx->mem_used -= b->size;
        free(b->data);
        free(b);
    }
}

void array_free(GlesContext *ctx)
{
    NameTable *t = &ctx->buffers;
    for (uint32_t i = 0; i < t->capacity; i++)
        if (t->keys[i] != NAME_EMPTY && t->keys[i] != NAME_DELETED)
            buffer_free(ctx, t->values[i]);
    names_free(t);
    t = &ctx->vaos;
    for (uint32_t i = 0; i < t->capacity; i++)
        if (t->keys[i] != NAME_EMPTY && t->keys[i] != NAME_DELETED)
            free(t->values[i]);
    names_free(t);
    ctx->vao = NULL;
}

int array_index_of_cap(GlesContext *ctx, unsigned int cap)
{
    for (int i = 0; i < ARR_TEXCOORD0; i++)
        if (array_caps[i] == cap)
            return i;
    if (cap == GL_TEXTURE_COORD_ARRAY)
        return ARR_TEXCOORD0 + (int)(ctx->client_active_texture - GL_TEXTURE0);
    return -1;
}

static void set_client_state(GlesContext *ctx, unsigned int cap, int on)
{
    int i = array_index_of_cap(ctx, cap);
    if (i < 0) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    ctx->arrays[i].enabled = on;
}

void gles_EnableClientState(GlesContext *ctx, unsigned int array) { set_client_state(ctx, array, 1); }
void gles_DisableClientState(GlesContext *ctx, unsigned int array) { set_client_state(ctx, array, 0); }

static int type_bytes(unsigned int type)
{
    switch (type) {
    case GL_BYTE: case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT: case GL_UNSIGNED_SHORT: return 2;
    case GL_FIXED: case GL_FLOAT: return 4;
    default: return 0;
    }
}

/* Table 2.4: which types each array accepts (bit per type) */
#define T_BYTE 1
#define T_UBYTE 2
#define T_SHORT 4
#define T_FIXED 8
#define T_FLOAT 16

static int type_bit(unsigned int type)
{
    switch (type) {
    case GL_BYTE: return T_BYTE;
    case GL_UNSIGNED_BYTE: return T_UBYTE;
    case GL_SHORT: return T_SHORT;
    case GL_FIXED: return T_FIXED;
    case GL_FLOAT: return T_FLOAT;
    default: return 0;
    }
}

static int set_pointer(GlesContext *ctx, int index, int size, int min_size, int max_size,
                        unsigned int type, int types, int stride, const void *ptr, int64_t nbytes)
{
    if (size < min_size || size > max_size || stride < 0) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return 0;
    }
    /* Common-Lite has no FLOAT arrays (Appendix C) */
    if (!(type_bit(type) & types) || (type == GL_FLOAT && ctx->profile == GLES_PROFILE_COMMON_LITE)) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return 0;
    }
    /* OES_vertex_array_object: an object holds buffer arrays only */
    if (ctx->vao && !ctx->array_buffer && ptr) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return 0;
    }
    ArrayState *a = &ctx->arrays[index];
    a->size = size;
    a->type = type;
    a->stride = stride;
    a->elem_bytes = size * type_bytes(type);
    a->step = stride ? stride : a->elem_bytes;
    a->ptr = ptr;
    a->buffer = ctx->array_buffer;
    a->buffer_name = ctx->array_buffer ? ctx->array_buffer->name : 0;
    a->nbytes = ctx->array_buffer ? -1 : nbytes;
    a->range_cached = 0;
    return 1;
}

int gles_VertexPointer(GlesContext *ctx, int size, unsigned int type, int stride, const void *ptr, int64_t nbytes)
{
    return set_pointer(ctx, ARR_VERTEX, size, 2, 4, type, T_BYTE | T_SHORT | T_FIXED | T_FLOAT, stride, ptr, nbytes);
}

int gles_ColorPointer(GlesContext *ctx, int size, unsigned int type, int stride, const void *ptr, int64_t nbytes)
{
    return set_pointer(ctx, ARR_COLOR, size, 4, 4, type, T_UBYTE | T_FIXED | T_FLOAT, stride, ptr, nbytes);
}

int gles_NormalPointer(GlesContext *ctx, unsigned int type, int stride, const void *ptr, int64_t nbytes)
{
    return set_pointer(ctx, ARR_NORMAL, 3, 3, 3, type, T_BYTE | T_SHORT | T_FIXED | T_FLOAT, stride, ptr, nbytes);
}

int gles_TexCoordPointer(GlesContext *ctx, int size, unsigned int type, int stride, const void *ptr, int64_t nbytes)
{
    int unit = (int)(ctx->client_active_texture - GL_TEXTURE0);
    return set_pointer(ctx, ARR_TEXCOORD0 + unit, size, 2, 4, type, T_BYTE | T_SHORT | T_FIXED | T_FLOAT, stride, ptr, nbytes);
}

int gles_PointSizePointerOES(GlesContext *ctx, unsigned int type, int stride, const void *ptr, int64_t nbytes)
{
    return set_pointer(ctx, ARR_POINT_SIZE, 1, 1, 1, type, T_FIXED | T_FLOAT, stride, ptr, nbytes);
}

int gles_MatrixIndexPointerOES(GlesContext *ctx, int size, unsigned int type, int stride, const void *ptr, int64_t nbytes)
{
    return set_pointer(ctx, ARR_MATRIX_INDEX, size, 1, GLES_MAX_VERTEX_UNITS, type, T_UBYTE, stride, ptr, nbytes);
}

int gles_WeightPointerOES(GlesContext *ctx, int size, unsigned int type, int stride, const void *ptr, int64_t nbytes)
{
    return set_pointer(ctx, ARR_WEIGHT, size, 1, GLES_MAX_VERTEX_UNITS, type, T_FIXED | T_FLOAT, stride, ptr, nbytes);
}

static ArrayState *array_of_pointer_pname(GlesContext *ctx, unsigned int pname)
{
    switch (pname) {
    case GL_VERTEX_ARRAY_POINTER: return &ctx->arrays[ARR_VERTEX];
    case GL_NORMAL_ARRAY_POINTER: return &ctx->arrays[ARR_NORMAL];
    case GL_COLOR_ARRAY_POINTER: return &ctx->arrays[ARR_COLOR];
    case GL_POINT_SIZE_ARRAY_POINTER_OES: return &ctx->arrays[ARR_POINT_SIZE];
    case GL_MATRIX_INDEX_ARRAY_POINTER_OES: return &ctx->arrays[ARR_MATRIX_INDEX];
    case GL_WEIGHT_ARRAY_POINTER_OES: return &ctx->arrays[ARR_WEIGHT];
    case GL_TEXTURE_COORD_ARRAY_POINTER:
        return &ctx->arrays[ARR_TEXCOORD0 + (int)(ctx->client_active_texture - GL_TEXTURE0)];
    default: return NULL;
    }
}

uintptr_t gles_GetPointer(GlesContext *ctx, unsigned int pname)
{
    uintptr_t debug_ptr;
    if (debug_pointer(ctx, pname, &debug_ptr))
        return debug_ptr;       /* KHR_debug's callback and its parameter */
    ArrayState *a = array_of_pointer_pname(ctx, pname);
    if (!a) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return 0;
    }
    return (uintptr_t)a->ptr;
}

int array_get(GlesContext *ctx, unsigned int pname, double *out, int *kind)
{
    static const struct { unsigned int size, type, stride, binding; int index; } q[] = {
        { GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_TYPE, GL_VERTEX_ARRAY_STRIDE, GL_VERTEX_ARRAY_BUFFER_BINDING, ARR_VERTEX },
        { 0, GL_NORMAL_ARRAY_TYPE, GL_NORMAL_ARRAY_STRIDE, GL_NORMAL_ARRAY_BUFFER_BINDING, ARR_NORMAL },
        { GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_TYPE, GL_COLOR_ARRAY_STRIDE, GL_COLOR_ARRAY_BUFFER_BINDING, ARR_COLOR },
        { 0, GL_POINT_SIZE_ARRAY_TYPE_OES, GL_POINT_SIZE_ARRAY_STRIDE_OES, GL_POINT_SIZE_ARRAY_BUFFER_BINDING_OES, ARR_POINT_SIZE },
        { GL_MATRIX_INDEX_ARRAY_SIZE_OES, GL_MATRIX_INDEX_ARRAY_TYPE_OES, GL_MATRIX_INDEX_ARRAY_STRIDE_OES,
          GL_MATRIX_INDEX_ARRAY_BUFFER_BINDING_OES, ARR_MATRIX_INDEX },
        { GL_WEIGHT_ARRAY_SIZE_OES, GL_WEIGHT_ARRAY_TYPE_OES, GL_WEIGHT_ARRAY_STRIDE_OES,
          GL_WEIGHT_ARRAY_BUFFER_BINDING_OES, ARR_WEIGHT },
        { GL_TEXTURE_COORD_ARRAY_SIZE, GL_TEXTURE_COORD_ARRAY_TYPE, GL_TEXTURE_COORD_ARRAY_STRIDE,
          GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, -1 },
    };
    for (size_t i = 0; i < sizeof q / sizeof q[0]; i++) {
        int idx = q[i].index >= 0 ? q[i].index : ARR_TEXCOORD0 + (int)(ctx->client_active_texture - GL_TEXTURE0);
        const ArrayState *a = &ctx->arrays[idx];
        if (q[i].size && pname == q[i].size) { *kind = GLES_KIND_INT; out[0] = a->size; return 1; }
        if (pname == q[i].type) { *kind = GLES_KIND_ENUM; out[0] = a->type; return 1; }
        if (pname == q[i].stride) { *kind = GLES_KIND_INT; out[0] = a->stride; return 1; }
        if (pname == q[i].binding) { *kind = GLES_KIND_INT; out[0] = a->buffer_name; return 1; }
    }
    int idx = array_index_of_cap(ctx, pname);
    if (idx >= 0) {
        *kind = GLES_KIND_BOOL;
        out[0] = ctx->arrays[idx].enabled;
        return 1;
    }
    if (pname == GL_VERTEX_ARRAY_BINDING_OES) {
        *kind = GLES_KIND_INT;
        out[0] = ctx->vao ? ctx->vao->name : 0;
        return 1;
    }
    return 0;
}

const uint8_t *array_base(const ArrayState *a)
{
    if (a->buffer)
        return a->buffer->data + (uintptr_t)a->ptr;
    return a->ptr;
}

static const char *array_label(int i)
{
    static const char *names[] = { "vertex", "normal", "color", "point size", "matrix index", "weight" };
    return i < ARR_TEXCOORD0 ? names[i] : "texture coordinate";
}

int array_check_range(GlesContext *ctx, int64_t max_index)
{
    for (int i = 0; i < ARR_COUNT; i++) {
        const ArrayState *a = &ctx->arrays[i];
        if (!a->enabled)
            continue;
        int64_t need = max_index * a->step + a->elem_bytes;
        if (a->buffer) {
            /* the buffer may have been deleted and re-specified since */
            const uint64_t offset = (uintptr_t)a->ptr;   /* 64 bits wide on every target */
            if (offset > (uint64_t)INT64_MAX || (int64_t)offset + need > a->buffer->size || !a->buffer->data)
                return ctx_message(ctx, GLES_EVALUE,
                                   "the %s array reads %lld bytes from offset %llu of buffer %u, which holds %lld",
                                   array_label(i), (long long)need, (unsigned long long)(uintptr_t)a->ptr,
                                   a->buffer->name, (long long)a->buffer->size);
        } else {
            if (!a->ptr)
                return ctx_message(ctx, GLES_EVALUE, "the %s array is enabled but has no pointer", array_label(i));
            if (a->nbytes >= 0 && need > a->nbytes)
                return ctx_message(ctx, GLES_EVALUE,
                                   "the %s array holds %lld bytes but the draw reads vertex %lld (%lld bytes)",
                                   array_label(i), (long long)a->nbytes, (long long)max_index, (long long)need);
        }
    }
    return GLES_OK;
}

/* Read an element with memcpy: client arrays need not be aligned. */
void array_fetch(const ArrayState *a, const uint8_t *base, int64_t index, int normalized, NUM *out)
{
    const uint8_t *p = base + index * a->step;
    int n = a->size;
    switch (a->type) {
    case GL_BYTE: {
        int8_t v[4];
        memcpy(v, p, (size_t)n);
        for (int i = 0; i < n; i++)
            out[i] = normalized ? num_from_snorm(v[i], 255) : num_from_int(v[i]);
        break;
    }
    case GL_UNSIGNED_BYTE: {
        uint8_t v[4];
        memcpy(v, p, (size_t)n);
        for (int i = 0; i < n; i++)
            out[i] = normalized ? num_from_unorm(v[i], 255) : num_from_int(v[i]);
        break;
    }
    case GL_SHORT: {
        int16_t v[4];
        memcpy(v, p, (size_t)n * 2);
        for (int i = 0; i < n; i++)
            out[i] = normalized ? num_from_snorm(v[i], 65535) : num_from_int(v[i]);
        break;
    }
    case GL_FIXED: {
        int32_t v[4];
        memcpy(v, p, (size_t)n * 4);
        for (int i = 0; i < n; i++)
            out[i] = num_from_fixed(v[i]);
        break;
    }
    default: { /* GL_FLOAT */
        float v[4];
        memcpy(v, p, (size_t)n * 4);
        for (int i = 0; i < n; i++)
            out[i] = num_from_double((double)v[i]);
        break;
    }
    }
}

/* {====================================================================
** buffer objects */

void gles_GenBuffers(GlesContext *ctx, int n, unsigned int *names)
{
    if (n < 0) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    names_generate(&ctx->buffers, n, names);
}

/* §2.9: arrays keep the name but read nothing once the buffer is gone;
** we detach them so a later draw reports the array as having no data */
static void detach_buffer(ArrayState arrays[ARR_COUNT], BufferObject **element_buffer, const BufferObject *b)
{
    if (*element_buffer == b)
        *element_buffer = NULL;
    for (int i = 0; i < ARR_COUNT; i++)
        if (arrays[i].buffer == b) {
            arrays[i].buffer = NULL;
            arrays[i].buffer_name = 0;
            arrays[i].ptr = NULL;
            arrays[i].nbytes = 0;
        }
}

static void unbind_everywhere(GlesContext *ctx, BufferObject *b)
{
    if (ctx->array_buffer == b)
        ctx->array_buffer = NULL;
    detach_buffer(ctx->arrays, &ctx->element_buffer, b);
    /* and in every vertex array object, bound or not (none may keep a
    ** pointer to the freed buffer) */
    detach_buffer(ctx->vao_default.arrays, &ctx->vao_default.element_buffer, b);
    const NameTable *t = &ctx->vaos;
    for (uint32_t i = 0; i < t->capacity; i++)
        if (t->keys[i] != NAME_EMPTY && t->keys[i] != NAME_DELETED) {
            VertexArrayObject *o = t->values[i];
            detach_buffer(o->state.arrays, &o->state.element_buffer, b);
        }
}

/* {====================================================================
** vertex array objects (OES_vertex_array_object) */

void gles_GenVertexArraysOES(GlesContext *ctx, int n, unsigned int *names)
{
    if (n < 0) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    /* the objects count against the memory budget, as buffer data does */
    if (!ctx_mem_fits(ctx, (int64_t)n * (int64_t)sizeof(VertexArrayObject), 0)) {
        ctx_error(ctx, GL_OUT_OF_MEMORY);
        return;
    }
    names_generate(&ctx->vaos, n, names);
    for (int i = 0; i < n; i++) {
        VertexArrayObject *o = calloc(1, sizeof *o);
        if (!o || !names_insert(&ctx->vaos, names[i], o)) {
            free(o);
            ctx_error(ctx, GL_OUT_OF_MEMORY);
            return;
        }
        o->name = names[i];
        arrays_default(ctx, o->state.arrays);
        ctx->mem_used += (int64_t)sizeof *o;
    }
}

void gles_BindVertexArrayOES(GlesContext *ctx, unsigned int name)
{
    VertexArrayObject *to = name ? names_lookup(&ctx->vaos, name) : NULL;
    if (name && !to) {
        /* not a name GenVertexArraysOES gave, or deleted since */
        ctx_error(ctx, GL_INVALID_OPERATION);
        return;
    }
    if (to)
        to->ever_bound = 1;
    if (to == ctx->vao)
        return;
    VertexArrayState *from = ctx->vao ? &ctx->vao->state : &ctx->vao_default;
    memcpy(from->arrays, ctx->arrays, sizeof ctx->arrays);
    from->element_buffer = ctx->element_buffer;
    const VertexArrayState *load = to ? &to->state : &ctx->vao_default;
    memcpy(ctx->arrays, load->arrays, sizeof ctx->arrays);
    ctx->element_buffer = load->element_buffer;
    ctx->vao = to;
}

void gles_DeleteVertexArraysOES(GlesContext *ctx, int n, const unsigned int *names)
{
    if (n < 0) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    for (int i = 0; i < n; i++) {
        VertexArrayObject *o = names[i] ? names_lookup(&ctx->vaos, names[i]) : NULL;
        if (!o)
            continue;   /* unused names are ignored */
        if (o == ctx->vao)
            gles_BindVertexArrayOES(ctx, 0);    /* the binding reverts to zero */
        names_remove(&ctx->vaos, names[i]);
        debug_object_deleted(ctx, DEBUG_NS_VERTEX_ARRAY, names[i]);
        free(o);
        ctx->mem_used -= (int64_t)sizeof *o;
    }
}

unsigned char gles_IsVertexArrayOES(GlesContext *ctx, unsigned int name)
{
    const VertexArrayObject *o = name ? names_lookup(&ctx->vaos, name) : NULL;
    return o && o->ever_bound;
}

/* }==================================================================== */

void gles_DeleteBuffers(GlesContext *ctx, int n, const unsigned int *names)
{
    if (n < 0) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    for (int i = 0; i < n; i++) {
        if (names[i] == 0)
            continue;
        BufferObject *b = names_remove(&ctx->buffers, names[i]);
        if (b) {
            debug_object_deleted(ctx, DEBUG_NS_BUFFER, names[i]);
            ctx->buffer_serial++;
            unbind_everywhere(ctx, b);
            buffer_free(ctx, b);
        }
    }
}

static BufferObject **binding_of(GlesContext *ctx, unsigned int target)
{
    if (target == GL_ARRAY_BUFFER)
        return &ctx->array_buffer;
    if (target == GL_ELEMENT_ARRAY_BUFFER)
        return &ctx->element_buffer;
    return NULL;
}

/* the buffer bound to target, or NULL with the GL error recorded: an
** unknown target INVALID_ENUM, buffer 0 INVALID_OPERATION */
static BufferObject *bound_buffer(GlesContext *ctx, unsigned int target)
{
    BufferObject **slot = binding_of(ctx, target);
    if (!slot) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return NULL;
    }
    if (!*slot)
        ctx_error(ctx, GL_INVALID_OPERATION);
    return *slot;
}

void gles_BindBuffer(GlesContext *ctx, unsigned int target, unsigned int buffer)
{
    BufferObject **slot = binding_of(ctx, target);
    if (!slot) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    if (buffer == 0) {
        *slot = NULL;
        return;
    }
    BufferObject *b = names_lookup(&ctx->buffers, buffer);
    if (!b) {
        b = calloc(1, sizeof *b);
        if (!b || !names_insert(&ctx->buffers, buffer, b)) {
            free(b);
            ctx_error(ctx, GL_OUT_OF_MEMORY);
            return;
        }
        b->name = buffer;
        b->usage = GL_STATIC_DRAW;
    }
    *slot = b;
}

int gles_BufferData(GlesContext *ctx, unsigned int target, int64_t size, const void *data, unsigned int usage)
{
    BufferObject **slot = binding_of(ctx, target);
    if (!slot || (usage != GL_STATIC_DRAW && usage != GL_DYNAMIC_DRAW)) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return GLES_OK;
    }
    if (size < 0) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return GLES_OK;
    }
    BufferObject *b = *slot;
    if (!b) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return GLES_OK;
    }
    /* past the memory budget (or malloc's) the buffer stays as it was
    ** (and stays mapped if it was; new data unmaps it) */
    int64_t held = b->data ? b->size : 0;
    uint8_t *store = ctx_mem_fits(ctx, size, held) && (uint64_t)size <= SIZE_MAX ? malloc(size ? (size_t)size : 1)
                                                                                 : NULL;
    if (!store) {
        ctx_error(ctx, GL_OUT_OF_MEMORY);
        return GLES_OK;
    }
    if (data)
        memcpy(store, data, (size_t)size);
    else
        memset(store, 0, (size_t)size);
    free(b->data);
    ctx->mem_used += size - held;
    ctx->buffer_serial++;
    b->data = store;
    b->size = size;
    b->usage = usage;
    b->mapped = 0;
    return GLES_OK;
}

void gles_BufferSubData(GlesContext *ctx, unsigned int target, int64_t offset, int64_t size, const void *data)
{
    BufferObject *b = bound_buffer(ctx, target);
    if (!b)
        return;
    if (offset < 0 || size < 0 || offset > b->size || size > b->size - offset) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    if (b->mapped) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return;
    }
    if (size && data) {
        memcpy(b->data + offset, data, (size_t)size);
        ctx->buffer_serial++;
    }
}

/* {====================================================================
** mapping (OES_mapbuffer, EXT_map_buffer_range) */

#define MAP_BITS (GL_MAP_READ_BIT_EXT | GL_MAP_WRITE_BIT_EXT | GL_MAP_INVALIDATE_RANGE_BIT_EXT \
                  | GL_MAP_INVALIDATE_BUFFER_BIT_EXT | GL_MAP_FLUSH_EXPLICIT_BIT_EXT | GL_MAP_UNSYNCHRONIZED_BIT_EXT)

void *gles_MapBufferRangeEXT(GlesContext *ctx, unsigned int target, int64_t offset, int64_t length,
                             unsigned int access)
{
    BufferObject *b = bound_buffer(ctx, target);
    if (!b)
        return NULL;
    if (offset < 0 || length < 0 || offset > b->size || length > b->size - offset || (access & ~(unsigned)MAP_BITS)) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return NULL;
    }
    const unsigned int rw = access & (GL_MAP_READ_BIT_EXT | GL_MAP_WRITE_BIT_EXT);
    if (length == 0 || b->mapped || !rw
        || ((access & GL_MAP_READ_BIT_EXT)
            && (access & (GL_MAP_INVALIDATE_RANGE_BIT_EXT | GL_MAP_INVALIDATE_BUFFER_BIT_EXT
                          | GL_MAP_UNSYNCHRONIZED_BIT_EXT)))
        || ((access & GL_MAP_FLUSH_EXPLICIT_BIT_EXT) && !(access & GL_MAP_WRITE_BIT_EXT))) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return NULL;
    }
    if (!b->data) {
        ctx_error(ctx, GL_OUT_OF_MEMORY);
        return NULL;
    }
    b->mapped = 1;
    b->map_access = access;
    b->map_offset = offset;
    b->map_length = length;
    return b->data + offset;
}

void *gles_MapBufferOES(GlesContext *ctx, unsigned int target, unsigned int access)
{
    BufferObject **slot = binding_of(ctx, target);
    if (!slot || access != GL_WRITE_ONLY_OES) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return NULL;
    }
    BufferObject *b = *slot;
    if (!b || b->mapped) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return NULL;
    }
    if (!b->data || b->size == 0) {
        /* no store to map (an empty buffer maps to nothing) */
        ctx_error(ctx, GL_OUT_OF_MEMORY);
        return NULL;
    }
    b->mapped = 1;
    b->map_access = GL_MAP_WRITE_BIT_EXT;
    b->map_offset = 0;
    b->map_length = b->size;
    return b->data;
}

void gles_FlushMappedBufferRangeEXT(GlesContext *ctx, unsigned int target, int64_t offset, int64_t length)
{
    BufferObject *b = bound_buffer(ctx, target);
    if (!b)
        return;
    if (offset < 0 || length < 0 || (b->mapped && (offset > b->map_length || length > b->map_length - offset))) {
        ctx_error(ctx, GL_INVALID_VALUE);
        return;
    }
    if (!b->mapped || !(b->map_access & GL_MAP_FLUSH_EXPLICIT_BIT_EXT)) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return;
    }
    ctx->buffer_serial++;       /* the range's data may have changed */
}

unsigned char gles_UnmapBufferOES(GlesContext *ctx, unsigned int target)
{
    BufferObject *b = bound_buffer(ctx, target);
    if (!b)
        return 0;
    if (!b->mapped) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return 0;
    }
    b->mapped = 0;
    if (b->map_access & GL_MAP_WRITE_BIT_EXT)
        ctx->buffer_serial++;
    return 1;       /* the store is memory: it is never lost */
}

int gles_GetBufferPointervOES(GlesContext *ctx, unsigned int target, unsigned int pname, void **out)
{
    BufferObject **slot = binding_of(ctx, target);
    if (!slot || pname != GL_BUFFER_MAP_POINTER_OES) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return 0;
    }
    BufferObject *b = *slot;
    if (!b) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return 0;
    }
    *out = b->mapped ? b->data + b->map_offset : NULL;
    return 1;
}

int gles_buffer_map_write(GlesContext *ctx, unsigned int target, int64_t offset, const void *data, int64_t nbytes)
{
    BufferObject **slot = binding_of(ctx, target);
    BufferObject *b = slot ? *slot : NULL;
    if (!b || !b->mapped || !(b->map_access & GL_MAP_WRITE_BIT_EXT))
        return ctx_message(ctx, GLES_EVALUE, "no write mapping of the buffer bound to 0x%04X", target);
    if (nbytes < 0 || offset < b->map_offset || nbytes > b->map_length - (offset - b->map_offset)
        || (nbytes && !data))
        return ctx_message(ctx, GLES_EVALUE, "%lld bytes at %lld fall outside the mapped range of buffer %u",
                           (long long)nbytes, (long long)offset, b->name);
    if (nbytes) {
        memcpy(b->data + offset, data, (size_t)nbytes);
        ctx->buffer_serial++;
    }
    return GLES_OK;
}

int array_reads_mapped(const GlesContext *ctx, int elements)
{
    if (elements && ctx->element_buffer && ctx->element_buffer->mapped)
        return 1;
    for (int i = 0; i < ARR_COUNT; i++)
        if (ctx->arrays[i].enabled && ctx->arrays[i].buffer && ctx->arrays[i].buffer->mapped)
            return 1;
    return 0;
}

/* }==================================================================== */

unsigned char gles_IsBuffer(GlesContext *ctx, unsigned int buffer)
{
    return names_lookup(&ctx->buffers, buffer) != NULL;
}

void gles_GetBufferParameteriv(GlesContext *ctx, unsigned int target, unsigned int pname, int *params)
{
    BufferObject **slot = binding_of(ctx, target);
    if (!slot) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    BufferObject *b = *slot;
    if (pname != GL_BUFFER_SIZE && pname != GL_BUFFER_USAGE && pname != GL_BUFFER_ACCESS_OES
        && pname != GL_BUFFER_MAPPED_OES) {
        ctx_error(ctx, GL_INVALID_ENUM);
        return;
    }
    if (!b) {
        ctx_error(ctx, GL_INVALID_OPERATION);
        return;
    }
    switch (pname) {
    case GL_BUFFER_SIZE: params[0] = (int)b->size; break;
    case GL_BUFFER_USAGE: params[0] = (int)b->usage; break;
    case GL_BUFFER_ACCESS_OES: params[0] = GL_WRITE_ONLY_OES; break;     /* ES 1's one access */
    default: params[0] = b->mapped; break;
    }
}
