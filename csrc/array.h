/*
** array.h -- vertex arrays, buffer objects, the name table and fetching.
*/
#ifndef GLES_ARRAY_H
#define GLES_ARRAY_H

#include "state.h"

void array_init(GlesContext *ctx);
void array_free(GlesContext *ctx);
/* ARR_* index of an array enable cap (VERTEX_ARRAY, ...), or -1 */
int array_index_of_cap(GlesContext *ctx, unsigned int cap);
/* array state queries (VERTEX_ARRAY_SIZE, ...): count or 0 */
int array_get(GlesContext *ctx, unsigned int pname, double *out, int *kind);
/* GLES_OK when every enabled array holds vertex max_index, else GLES_EVALUE
** with a message naming the array */
int array_check_range(GlesContext *ctx, int64_t max_index);
/* whether a draw would read a mapped buffer: an enabled array's, or with
** `elements` the element array buffer (INVALID_OPERATION) */
int array_reads_mapped(const GlesContext *ctx, int elements);
/* base address of an enabled array's data (client memory or buffer store) */
const uint8_t *array_base(const ArrayState *a);
/* read element `index` of array `a` into out[0..size-1] as NUM, converting
** per Table 2.7 when `normalized` (normals and colours) */
void array_fetch(const ArrayState *a, const uint8_t *base, int64_t index, int normalized, NUM *out);

/* name table (shared with texture objects) */
void names_init(NameTable *t);
void names_free(NameTable *t);
void *names_lookup(const NameTable *t, unsigned int name);
int names_insert(NameTable *t, unsigned int name, void *value);  /* 0 on no memory */
void *names_remove(NameTable *t, unsigned int name);
/* n unused names, reserved (lookup gives NULL until inserted) */
void names_generate(NameTable *t, int n, unsigned int *out);

#endif
