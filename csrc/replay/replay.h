/*
** replay.h -- run a trace of core calls (the .glestrace format written by
** gles.trace, see docs/target.md) against the core of the build this is
** linked with. No I/O here: the caller hands over the whole file in memory,
** 8-byte aligned (blobs inside the file are aligned to 8 from its start, and
** the core reads them in place).
*/
#ifndef GLES_REPLAY_H
#define GLES_REPLAY_H

#include <stddef.h>
#include <stdint.h>

#include "gles_core.h"

#define REPLAY_VERSION 1
#define REPLAY_HEADER_SIZE 40

/* the markers a replay passes to its hook: the frame begins (at the trace's
** frame record, or once the context exists when it has none), and ends (at
** the end record, before the framebuffer is read) */
#define REPLAY_MARK_BEGIN 1
#define REPLAY_MARK_END 2

/* output buffers of one call at most (GetDebugMessageLogKHR has six) */
#define REPLAY_OUTPUT_SLOTS 8

typedef struct ReplayHeader {
    uint32_t table_hash;
    int width, height, color, depth, stencil, profile;
    int numeric;          /* the build that recorded it: 0 fixed, 1 float, 2 double */
    int range_mode;       /* GLES_RANGE_* */
    int64_t memory_limit;
} ReplayHeader;

typedef struct ReplayRegion {
    uint8_t *data;
    uint64_t size;
} ReplayRegion;

typedef struct Replay {
    ReplayHeader header;
    GlesContext *ctx;                 /* valid after a successful replay_run */
    void (*marker)(void *user, int which);
    void *user;
    uint64_t calls;                   /* core calls made */
    int frames;                       /* frame records (0 or 1) */
    /* private */
    ReplayRegion *regions;
    uint32_t region_count, region_cap;
    uint64_t region_bytes;
    void *scratch[REPLAY_OUTPUT_SLOTS];
    uint64_t scratch_size[REPLAY_OUTPUT_SLOTS];
    char error[256];
} Replay;

/* checks the whole trace, then creates the context and makes every call;
** returns 0, or -1 with the reason in rp->error (rp->ctx is then NULL) */
int replay_run(Replay *rp, const uint8_t *data, size_t size);
/* bytes of the colour buffer (gles_color_buffer) */
size_t replay_color_bytes(const Replay *rp);
void replay_free(Replay *rp);

#endif
