/*
** replay.c -- the trace decoder and player (see replay.h). Every read is
** bounds-checked; the whole trace is checked in a first pass that makes no
** call, so a bad file is refused before any GL state exists. Counts and
** sizes that the core trusts (n names, size bytes of data, an offset while a
** buffer is bound) are checked against what the trace actually holds.
*/
#include "replay.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define REC_REGION_DEF 0xFF00u
#define REC_REGION_DATA 0xFF01u
#define REC_FRAME 0xFF02u
#define REC_END 0xFF03u

#define MAX_REGION_BYTES ((uint64_t)1 << 28)   /* client arrays held at once */
#define MAX_OUTPUT_BYTES ((uint64_t)1 << 26)   /* one output buffer */
#define MIN_OUTPUT_BYTES 128u                  /* gles_get writes up to 16 doubles */

static const uint8_t MAGIC[8] = {'G', 'L', 'E', 'S', 'T', 'R', 'C', 0x1a};

typedef struct Reader {
    const uint8_t *base, *p, *end;
    int failed;
    const char *why;
} Reader;

typedef struct ReplayDatum {
    void *ptr;
    int64_t nbytes;
} ReplayDatum;

static void rd_fail(Reader *r, const char *why)
{
    if (!r->failed) {
        r->failed = 1;
        r->why = why;
    }
}

static const uint8_t *rd_take(Reader *r, uint64_t n)
{
    if (r->failed)
        return NULL;
    if (n > (uint64_t)(r->end - r->p)) {
        rd_fail(r, "truncated");
        r->p = r->end;
        return NULL;
    }
    const uint8_t *at = r->p;
    r->p += n;
    return at;
}

static uint64_t rd_le(Reader *r, int n)
{
    const uint8_t *b = rd_take(r, (uint64_t)n);
    uint64_t v = 0;
    if (b == NULL)
        return 0;
    for (int i = n - 1; i >= 0; i--)
        v = v << 8 | b[i];
    return v;
}

static uint8_t rd_u8(Reader *r) { return (uint8_t)rd_le(r, 1); }
static uint16_t rd_u16(Reader *r) { return (uint16_t)rd_le(r, 2); }
static uint32_t rd_u32(Reader *r) { return (uint32_t)rd_le(r, 4); }

static int32_t rd_i32(Reader *r)
{
    uint32_t u = rd_u32(r);
    int32_t v;
    memcpy(&v, &u, sizeof v);     /* two's complement, without the implementation-defined cast */
    return v;
}

static int64_t rd_i64(Reader *r)
{
    uint64_t u = rd_le(r, 8);
    int64_t v;
    memcpy(&v, &u, sizeof v);
    return v;
}

static double rd_f64(Reader *r)
{
    uint64_t u = rd_le(r, 8);
    double v;
    memcpy(&v, &u, sizeof v);
    return v;
}

/* blobs start 8-aligned from the start of the file; the padding is zero */
static void rd_align(Reader *r)
{
    size_t pad = (size_t)(-(size_t)(r->p - r->base) & 7u);
    const uint8_t *b = rd_take(r, pad);
    for (size_t i = 0; b != NULL && i < pad; i++)
        if (b[i] != 0)
            rd_fail(r, "non-zero padding");
}

static void rd_doubles(Reader *r, double out[16])
{
    uint32_t n = rd_u32(r);
    memset(out, 0, 16 * sizeof out[0]);
    if (n > 16) {
        rd_fail(r, "more than 16 values");
        return;
    }
    for (uint32_t i = 0; i < n; i++)
        out[i] = rd_f64(r);
}

static uint32_t rd_uints(Reader *r, const unsigned int **out)
{
    static const unsigned int none[1] = {0};
    uint32_t n = rd_u32(r);
    rd_align(r);
    const uint8_t *b = rd_take(r, (uint64_t)n * 4u);
    *out = (b != NULL && n > 0) ? (const unsigned int *)(const void *)b : none;
    return b != NULL ? n : 0;
}

static void rd_datum(Replay *rp, Reader *r, ReplayDatum *d, int with_len, unsigned binding, int run)
{
    static const uint8_t empty[8];
    uint8_t tag = rd_u8(r);
    d->ptr = NULL;
    d->nbytes = 0;
    switch (tag) {
    case 0:
        break;
    case 1: {
        uint64_t off = rd_le(r, 8);
        if (!with_len) {
            rd_fail(r, "a buffer offset where data is needed");
        } else if (off > (uint64_t)UINTPTR_MAX) {
            rd_fail(r, "buffer offset out of range");
        } else if (run && off != 0) {
            double bound[16];
            int kind;
            gles_get(rp->ctx, binding, bound, &kind);
            if (bound[0] == 0.0)
                rd_fail(r, "a buffer offset with no buffer bound");
        }
        d->ptr = (void *)(uintptr_t)off;
        d->nbytes = -1;
        break;
    }
    case 2: {
        uint64_t n = rd_le(r, 8);
        rd_align(r);
        const uint8_t *b = rd_take(r, n);
        d->ptr = (void *)(uintptr_t)(b != NULL && n > 0 ? b : empty);
        d->nbytes = (int64_t)n;
        break;
    }
    case 3: {
        uint32_t id = rd_u32(r);
        if (!with_len) {
            rd_fail(r, "a client array where data is needed");
        } else if (id >= rp->region_count) {
            rd_fail(r, "undefined client array");
        } else {
            d->ptr = rp->regions[id].data;
            d->nbytes = (int64_t)rp->regions[id].size;
        }
        break;
    }
    default:
        rd_fail(r, "unknown data tag");
    }
}

static void rd_output(Replay *rp, Reader *r, ReplayDatum *d, int slot)
{
    uint32_t size = rd_u32(r);
    d->ptr = NULL;
    d->nbytes = 0;
    if (r->failed || size == 0xFFFFFFFFu)
        return;
    if (size > MAX_OUTPUT_BYTES) {
        rd_fail(r, "output buffer too large");
        return;
    }
    uint64_t want = size < MIN_OUTPUT_BYTES ? MIN_OUTPUT_BYTES : size;
    if (rp->scratch_size[slot] < want) {
        void *p = realloc(rp->scratch[slot], (size_t)want);
        if (p == NULL) {
            rd_fail(r, "out of memory");
            return;
        }
        rp->scratch[slot] = p;
        rp->scratch_size[slot] = want;
    }
    d->ptr = rp->scratch[slot];
    d->nbytes = size;
}

#include "calls.h"

static void set_error(Replay *rp, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(rp->error, sizeof rp->error, fmt, ap);
    va_end(ap);
}

static int read_header(Replay *rp, Reader *r)
{
    ReplayHeader *h = &rp->header;
    const uint8_t *magic = rd_take(r, 8);
    if (magic == NULL || memcmp(magic, MAGIC, 8) != 0) {
        set_error(rp, "not a gles trace (bad magic)");
        return -1;
    }
    if (r->end - r->base < REPLAY_HEADER_SIZE) {
        set_error(rp, "truncated trace header (%lu bytes)", (unsigned long)(r->end - r->base));
        return -1;
    }
    unsigned version = rd_u16(r), header_size = rd_u16(r);
    if (version != REPLAY_VERSION) {
        set_error(rp, "trace format version %u, this replayer reads version %d", version, REPLAY_VERSION);
        return -1;
    }
    h->table_hash = rd_u32(r);
    h->width = rd_u16(r);
    h->height = rd_u16(r);
    h->color = rd_u8(r);
    h->depth = rd_u8(r);
    h->stencil = rd_u8(r);
    h->profile = rd_u8(r);
    h->numeric = rd_u8(r);
    h->range_mode = rd_u8(r);
    (void)rd_u16(r);
    (void)rd_u32(r);
    h->memory_limit = rd_i64(r);
    if (r->failed || header_size != REPLAY_HEADER_SIZE) {
        set_error(rp, "truncated or malformed trace header");
        return -1;
    }
    if (h->table_hash != REPLAY_TABLE_HASH) {
        set_error(rp, "trace call table 0x%08X, this replayer has 0x%08X (a different version of gles)",
                  (unsigned)h->table_hash, (unsigned)REPLAY_TABLE_HASH);
        return -1;
    }
    if (h->width < 1 || h->width > 4096 || h->height < 1 || h->height > 4096 || h->color > GLES_COLOR_RGBA5551 ||
        (h->depth != 0 && h->depth != 16 && h->depth != 24) || (h->stencil != 0 && h->stencil != 8) ||
        h->profile > 1 || h->numeric > 2 || h->range_mode > 2 || h->memory_limit < 0) {
        set_error(rp, "invalid context configuration in the trace header");
        return -1;
    }
    return 0;
}

static void free_regions(Replay *rp)
{
    for (uint32_t i = 0; i < rp->region_count; i++)
        free(rp->regions[i].data);
    rp->region_count = 0;
    rp->region_bytes = 0;
}

/* one pass over the records: run = 0 checks, run = 1 plays */
static int records(Replay *rp, Reader *r, int run)
{
    uint64_t index = 0;
    unsigned id = 0;
    int frames = 0;
    for (;; index++) {
        const uint8_t *at = r->p;
        if (r->p == r->end) {
            set_error(rp, "truncated: the trace ends at byte %lu without its end record",
                      (unsigned long)(r->p - r->base));
            return -1;
        }
        id = rd_u16(r);
        if (id == REC_END) {
            if (r->p != r->end) {
                set_error(rp, "%lu bytes after the end record", (unsigned long)(r->end - r->p));
                return -1;
            }
            if (run && rp->marker)
                rp->marker(rp->user, REPLAY_MARK_END);
            rp->frames = frames;
            return 0;
        }
        if (id == REC_FRAME) {
            if (++frames > 1)
                rd_fail(r, "more than one frame record");
            else if (run && rp->marker)
                rp->marker(rp->user, REPLAY_MARK_BEGIN);
        } else if (id == REC_REGION_DEF) {
            uint32_t rid = rd_u32(r);
            uint64_t size = rd_le(r, 8);
            if (r->failed) {
                /* reported below */
            } else if (rid != rp->region_count) {
                rd_fail(r, "client arrays out of order");
            } else if (size > MAX_REGION_BYTES - rp->region_bytes) {
                rd_fail(r, "client arrays too large");
            } else {
                if (rp->region_count == rp->region_cap) {
                    uint32_t cap = rp->region_cap ? 2 * rp->region_cap : 16;
                    void *p = realloc(rp->regions, cap * sizeof *rp->regions);
                    if (p == NULL) {
                        rd_fail(r, "out of memory");
                        goto failed;
                    }
                    rp->regions = p;
                    rp->region_cap = cap;
                }
                /* +8: never empty, so an empty array is not a null pointer */
                uint8_t *mem = calloc(1, (size_t)size + 8);
                if (mem == NULL) {
                    rd_fail(r, "out of memory");
                    goto failed;
                }
                rp->regions[rp->region_count++] = (ReplayRegion){mem, size};
                rp->region_bytes += size;
            }
        } else if (id == REC_REGION_DATA) {
            uint32_t rid = rd_u32(r);
            uint64_t size = rd_le(r, 8);
            rd_align(r);
            const uint8_t *b = rd_take(r, size);
            if (r->failed) {
                /* reported below */
            } else if (rid >= rp->region_count || rp->regions[rid].size != size) {
                rd_fail(r, "client array data does not match its array");
            } else if (run) {
                memcpy(rp->regions[rid].data, b, (size_t)size);
            }
        } else if (id < REPLAY_CALL_COUNT) {
            replay_call(rp, r, id, run);
            if (run && !r->failed)
                rp->calls++;
        } else {
            rd_fail(r, "unknown record");
        }
    failed:
        if (r->failed) {
            set_error(rp, "record %lu (%s) at byte %lu: %s", (unsigned long)index,
                      id < REPLAY_CALL_COUNT ? replay_call_names[id] : "special",
                      (unsigned long)(at - r->base), r->why);
            return -1;
        }
    }
}

int replay_run(Replay *rp, const uint8_t *data, size_t size)
{
    Reader r = {data, data, data + size, 0, NULL};
    rp->ctx = NULL;
    rp->calls = 0;
    rp->error[0] = 0;
    if (((uintptr_t)data & 7u) != 0) {
        set_error(rp, "the trace must be 8-byte aligned in memory");
        return -1;
    }
    if (read_header(rp, &r) != 0)
        return -1;
    const uint8_t *first = r.p;
    /* pass 1: check everything, call nothing */
    if (records(rp, &r, 0) != 0) {
        free_regions(rp);
        return -1;
    }
    free_regions(rp);
    const ReplayHeader *h = &rp->header;
    rp->ctx = gles_context_create(h->width, h->height, h->color, h->depth, h->stencil, h->profile);
    if (rp->ctx == NULL) {
        set_error(rp, "could not create a %dx%d context", h->width, h->height);
        return -1;
    }
    gles_range_set(rp->ctx, h->range_mode);
    gles_memory_limit(rp->ctx, h->memory_limit);
    int had_frame = rp->frames;
    if (!had_frame && rp->marker)
        rp->marker(rp->user, REPLAY_MARK_BEGIN);
    r = (Reader){data, first, data + size, 0, NULL};
    if (records(rp, &r, 1) != 0) {
        gles_context_destroy(rp->ctx);
        rp->ctx = NULL;
        return -1;
    }
    return 0;
}

size_t replay_color_bytes(const Replay *rp)
{
    int bpp = rp->header.color == GLES_COLOR_RGBA8888 ? 4 : 2;
    return (size_t)rp->header.width * (size_t)rp->header.height * (size_t)bpp;
}

void replay_free(Replay *rp)
{
    if (rp->ctx != NULL)
        gles_context_destroy(rp->ctx);
    rp->ctx = NULL;
    free_regions(rp);
    free(rp->regions);
    rp->regions = NULL;
    rp->region_cap = 0;
    for (int i = 0; i < REPLAY_OUTPUT_SLOTS; i++) {
        free(rp->scratch[i]);
        rp->scratch[i] = NULL;
        rp->scratch_size[i] = 0;
    }
}
