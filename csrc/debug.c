/*
** debug.c -- KHR_debug (its OpenGL ES form: KHR-suffixed commands and
** tokens): debug output and object labels.
** Consumes: the errors ctx_error records (debug_error), the debug commands.
** Produces: messages, each to the application's callback, the binding's
**       queue or the bounded log; labels of the objects gles has.
**
** Filtering follows §5.5.4's model of an enabled state per message: per
** debug group, each (source, type) namespace keeps the severities enabled
** for IDs without a rule of their own (`defaults`), and a rule per ID named
** by DebugMessageControl holds that ID's severities. A control by source,
** type and severity changes the defaults and every matching rule alike; a
** control by IDs sets each named ID's rule whole. A push copies the group.
**
** Output is synchronous always: every message is raised by the command
** that causes it on the calling thread (worker threads record no errors).
*/
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "debug.h"

enum { DEBUG_SOURCES = 6, DEBUG_TYPES = 9 };
/* severity bits of a namespace's or an ID's enabled state */
enum { SEV_HIGH = 1, SEV_MEDIUM = 2, SEV_LOW = 4, SEV_NOTIFICATION = 8, SEV_ALL = 15 };
/* §5.5.1: "All messages are initially enabled unless their assigned
** severity is DEBUG_SEVERITY_LOW" */
#define SEV_INITIAL (SEV_ALL & ~SEV_LOW)

typedef struct LoggedMessage {
    unsigned int source, type, id, severity;
    int length;         /* bytes of text, terminator included */
    char *text;
} LoggedMessage;

/* a ring of messages, at most `limit` (grown on demand) */
typedef struct MessageRing {
    LoggedMessage *items;
    int capacity, start, count, limit;
} MessageRing;

typedef struct MessageRule {
    uint64_t key;       /* namespace << 32 | id */
    uint8_t severities;
} MessageRule;

typedef struct MessageGroup {
    unsigned int source, id;    /* the push's, repeated by the pop's message */
    char *message;
    int length;                 /* bytes of message, terminator included */
    uint8_t defaults[DEBUG_SOURCES * DEBUG_TYPES];
    MessageRule *rules;           /* sorted by key */
    int rule_count, rule_capacity;
} MessageGroup;

typedef struct ObjectLabel {
    uint64_t key;       /* namespace << 32 | name */
    char *text;
    int length;         /* characters, no terminator */
} ObjectLabel;

struct DebugState {
    int synchronous;
    GlesDebugProc callback;
    const void *user_param;
    int queue_on;               /* the binding's callback: messages into `queue` */
    int in_callback;            /* messages raised inside the callback go to the log */
    MessageRing log, queue;
    MessageGroup groups[DEBUG_MAX_GROUP_STACK_DEPTH];
    int depth;                  /* groups in use, the default one included */
    ObjectLabel *labels;         /* sorted by key */
    int label_count, label_capacity;
};

static const unsigned int debug_sources[DEBUG_SOURCES] = {
    GL_DEBUG_SOURCE_API_KHR, GL_DEBUG_SOURCE_WINDOW_SYSTEM_KHR, GL_DEBUG_SOURCE_SHADER_COMPILER_KHR,
    GL_DEBUG_SOURCE_THIRD_PARTY_KHR, GL_DEBUG_SOURCE_APPLICATION_KHR, GL_DEBUG_SOURCE_OTHER_KHR,
};
static const unsigned int debug_types[DEBUG_TYPES] = {
    GL_DEBUG_TYPE_ERROR_KHR, GL_DEBUG_TYPE_DEPRECATED_BEHAVIOR_KHR, GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR_KHR,
    GL_DEBUG_TYPE_PORTABILITY_KHR, GL_DEBUG_TYPE_PERFORMANCE_KHR, GL_DEBUG_TYPE_OTHER_KHR,
    GL_DEBUG_TYPE_MARKER_KHR, GL_DEBUG_TYPE_PUSH_GROUP_KHR, GL_DEBUG_TYPE_POP_GROUP_KHR,
};

static int debug_source_index(unsigned int source)
{
    for (int i = 0; i < DEBUG_SOURCES; i++)
        if (debug_sources[i] == source)
            return i;
    return -1;
}

static int debug_type_index(unsigned int type)
{
    for (int i = 0; i < DEBUG_TYPES; i++)
        if (debug_types[i] == type)
            return i;
    return -1;
}

static int debug_severity_bit(unsigned int severity)
{
    switch (severity) {
    case GL_DEBUG_SEVERITY_HIGH_KHR: return SEV_HIGH;
    case GL_DEBUG_SEVERITY_MEDIUM_KHR: return SEV_MEDIUM;
    case GL_DEBUG_SEVERITY_LOW_KHR: return SEV_LOW;
    case GL_DEBUG_SEVERITY_NOTIFICATION_KHR: return SEV_NOTIFICATION;
    default: return 0;
    }
}

/* {====================================================================
** state */

static void debug_group_clear(MessageGroup *g)
{
    free(g->message);
    free(g->rules);
    memset(g, 0, sizeof *g);
}

static void debug_ring_clear(MessageRing *r)
{
    for (int i = 0; i < r->count; i++)
        free(r->items[(r->start + i) % r->capacity].text);
    free(r->items);
    r->items = NULL;
    r->capacity = r->start = r->count = 0;
}

int debug_init(GlesContext *ctx)
{
    DebugState *d = calloc(1, sizeof *d);
    if (!d)
        return 0;
    d->log.limit = DEBUG_MAX_LOGGED_MESSAGES;
    d->queue.limit = DEBUG_MAX_QUEUED_MESSAGES;
    d->depth = 1;
    memset(d->groups[0].defaults, SEV_INITIAL, sizeof d->groups[0].defaults);
    ctx->dbg = d;
    ctx->debug_output = 0;
    return 1;
}

void debug_free(GlesContext *ctx)
{
    DebugState *d = ctx->dbg;
    if (!d)
        return;
    for (int i = 0; i < d->depth; i++)
        debug_group_clear(&d->groups[i]);
    debug_ring_clear(&d->log);
    debug_ring_clear(&d->queue);
    for (int i = 0; i < d->label_count; i++)
        free(d->labels[i].text);
    free(d->labels);
    free(d);
    ctx->dbg = NULL;
}

void gles_debug_context_set(GlesContext *ctx, int on)
{
    /* KHR_debug §5.5: a debug context starts with DEBUG_OUTPUT enabled */
    ctx->debug_output = on != 0;
}

int debug_set_enable(GlesContext *ctx, unsigned int cap, int on)
{
    if (cap == GL_DEBUG_OUTPUT_KHR)
        ctx->debug_output = on;
    else if (cap == GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR)
        ctx->dbg->synchronous = on;
    else
        return 0;
    return 1;
}

int debug_is_enabled(const GlesContext *ctx, unsigned int cap, unsigned char *out)
{
    if (cap == GL_DEBUG_OUTPUT_KHR)
        *out = (unsigned char)ctx->debug_output;
    else if (cap == GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR)
        *out = (unsigned char)ctx->dbg->synchronous;
    else
        return 0;
    return 1;
}

int debug_get(GlesContext *ctx, unsigned int pname, double *out, int *kind)
{
    const DebugState *d = ctx->dbg;
    double v;
    switch (pname) {
    case GL_DEBUG_LOGGED_MESSAGES_KHR: v = d->log.count; break;
    case GL_DEBUG_NEXT_LOGGED_MESSAGE_LENGTH_KHR:
        v = d->log.count ? d->log.items[d->log.start].length : 0;
        break;
    case GL_DEBUG_GROUP_STACK_DEPTH_KHR: v = d->depth; break;
    case GL_MAX_DEBUG_MESSAGE_LENGTH_KHR: v = DEBUG_MAX_MESSAGE_LENGTH; break;
    case GL_MAX_DEBUG_LOGGED_MESSAGES_KHR: v = DEBUG_MAX_LOGGED_MESSAGES; break;
    case GL_MAX_DEBUG_GROUP_STACK_DEPTH_KHR: v = DEBUG_MAX_GROUP_STACK_DEPTH; break;
    case GL_MAX_LABEL_LENGTH_KHR: v = DEBUG_MAX_LABEL_LENGTH; break;
    case GL_DEBUG_OUTPUT_KHR: case GL_DEBUG_OUTPUT_SYNCHRONOUS_KHR: {
        unsigned char on = 0;
        debug_is_enabled(ctx, pname, &on);
        out[0] = on;
        *kind = GLES_KIND_BOOL;
        return 1;
    }
    default: return 0;
    }
    out[0] = v;
    *kind = GLES_KIND_INT;
    return 1;
}

int debug_pointer(GlesContext *ctx, unsigned int pname, uintptr_t *out)
{
    if (pname == GL_DEBUG_CALLBACK_FUNCTION_KHR)
        *out = (uintptr_t)ctx->dbg->callback;
    else if (pname == GL_DEBUG_CALLBACK_USER_PARAM_KHR)
        *out = (uintptr_t)ctx->dbg->user_param;
    else
        return 0;
    return 1;
}

/* }==================================================================== */

/* {====================================================================
** filters */

static uint64_t debug_rule_key(int s, int t, unsigned int id)
{
    return (uint64_t)(s * DEBUG_TYPES + t) << 32 | id;
}

/* the index of the first of `count` items (each `stride` bytes, a uint64_t
** key first, ascending) whose key is >= key: the rules and the labels */
_Static_assert(offsetof(MessageRule, key) == 0 && offsetof(ObjectLabel, key) == 0, "keys lead their items");
static int debug_lower_bound(const void *items, size_t stride, int count, uint64_t key)
{
    int lo = 0, hi = count;
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        uint64_t k;
        memcpy(&k, (const char *)items + (size_t)mid * stride, sizeof k);
        if (k < key)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

static int debug_rule_find(const MessageGroup *g, uint64_t key)
{
    return debug_lower_bound(g->rules, sizeof *g->rules, g->rule_count, key);
}

static int debug_enabled(const MessageGroup *g, int s, int t, unsigned int id, int severity_bit)
{
    uint64_t key = debug_rule_key(s, t, id);
    int i = debug_rule_find(g, key);
    uint8_t on = i < g->rule_count && g->rules[i].key == key ? g->rules[i].severities : g->defaults[s * DEBUG_TYPES + t];
    return (on & severity_bit) != 0;
}

/* one ID's rule set whole: 0 without memory */
static int debug_rule_set(MessageGroup *g, uint64_t key, uint8_t severities)
{
    int i = debug_rule_find(g, key);
    if (i < g->rule_count && g->rules[i].key == key) {
        g->rules[i].severities = severities;
        return 1;
    }
    if (g->rule_count == g->rule_capacity) {
        int cap = g->rule_capacity ? 2 * g->rule_capacity : 16;
        MessageRule *r = realloc(g->rules, (size_t)cap * sizeof *r);
        if (!r)
            return 0;
        g->rules = r;
        g->rule_capacity = cap;
    }
    memmove(&g->rules[i + 1], &g->rules[i], (size_t)(g->rule_count - i) * sizeof *g->rules);
    g->rules[i].key = key;
    g->rules[i].severities = severities;
    g->rule_count++;
    return 1;
}

static int debug_group_copy(MessageGroup *to, const MessageGroup *from)
{
    memcpy(to->defaults, from->defaults, sizeof to->defaults);
    to->rules = NULL;
    to->rule_count = to->rule_capacity = 0;
    if (from->rule_count) {
        to->rules = malloc((size_t)from->rule_count * sizeof *to->rules);
        if (!to->rules)
            return 0;
        memcpy(to->rules, from->rules, (size_t)from->rule_count * sizeof *to->rules);
        to->rule_count = to->rule_capacity = from->rule_count;
    }
    return 1;
}

void gles_DebugMessageControlKHR(GlesContext *ctx, unsigned int source, unsigned int type, unsigned int severity,
                                 int n, const unsigned int *ids, unsigned char enabled)
{
    int s = source == GL_DONT_CARE ? -1 : debug_source_index(source);
    int t = type == GL_DONT_CARE ? -1 : debug_type_index(type);
    int bits = severity == GL_DONT_CARE ? SEV_ALL : debug_severity_bit(severity);
    if ((source != GL_DONT_CARE && s < 0) || (type != GL_DONT_CARE && t < 0) || !bits) {
        ctx_error_why(ctx, GL_INVALID_ENUM, "source, type or severity is not DONT_CARE or a KHR_debug value");
        return;
    }
    if (n < 0) {
        ctx_error_why(ctx, GL_INVALID_VALUE, "count is negative");
        return;
    }
    if (n > 0 && (s < 0 || t < 0 || severity != GL_DONT_CARE)) {
        ctx_error_why(ctx, GL_INVALID_OPERATION, "IDs need one source and one type, and severity DONT_CARE");
        return;
    }
    MessageGroup *g = &ctx->dbg->groups[ctx->dbg->depth - 1];
    if (n > 0) {
        if (!ids)
            return;
        for (int i = 0; i < n; i++)
            if (!debug_rule_set(g, debug_rule_key(s, t, ids[i]), enabled ? SEV_ALL : 0)) {
                ctx_error_why(ctx, GL_OUT_OF_MEMORY, "no memory for the message IDs' states");
                return;
            }
        return;
    }
    for (int si = 0; si < DEBUG_SOURCES; si++) {
        if (s >= 0 && si != s)
            continue;
        for (int ti = 0; ti < DEBUG_TYPES; ti++) {
            if (t >= 0 && ti != t)
                continue;
            uint8_t *def = &g->defaults[si * DEBUG_TYPES + ti];
            *def = (uint8_t)(enabled ? *def | bits : *def & ~bits);
        }
    }
    for (int i = 0; i < g->rule_count; i++) {
        int ns = (int)(g->rules[i].key >> 32), si = ns / DEBUG_TYPES, ti = ns % DEBUG_TYPES;
        if ((s < 0 || si == s) && (t < 0 || ti == t)) {
            uint8_t *r = &g->rules[i].severities;
            *r = (uint8_t)(enabled ? *r | bits : *r & ~bits);
        }
    }
}

/* }==================================================================== */

/* {====================================================================
** messages */

static LoggedMessage *debug_ring_push(MessageRing *r)
{
    if (r->count == r->limit)
        return NULL;    /* §5.5.3: a full log discards what comes after */
    if (r->count == r->capacity) {
        int cap = r->capacity ? 2 * r->capacity : 16;
        if (cap > r->limit)
            cap = r->limit;
        LoggedMessage *items = malloc((size_t)cap * sizeof *items);
        if (!items)
            return NULL;
        for (int i = 0; i < r->count; i++)
            items[i] = r->items[(r->start + i) % r->capacity];
        free(r->items);
        r->items = items;
        r->capacity = cap;
        r->start = 0;
    }
    return &r->items[(r->start + r->count++) % r->capacity];
}

/* one message, `length` characters of text (no terminator counted),
** filtered by debug group `level` */
static void debug_emit_in(GlesContext *ctx, int level, unsigned int source, unsigned int type, unsigned int id,
                          unsigned int severity, const char *text, int length)
{
    DebugState *d = ctx->dbg;
    if (!ctx->debug_output || !d)
        return;
    if (!debug_enabled(&d->groups[level], debug_source_index(source), debug_type_index(type), id,
                       debug_severity_bit(severity)))
        return;
    if (length > DEBUG_MAX_MESSAGE_LENGTH - 1)
        length = DEBUG_MAX_MESSAGE_LENGTH - 1;
    if (d->callback && !d->in_callback) {
        /* the text handed over is terminated where length says */
        char copy[DEBUG_MAX_MESSAGE_LENGTH];
        memcpy(copy, text, (size_t)length);
        copy[length] = '\0';
        d->in_callback = 1;
        d->callback(source, type, id, severity, length, copy, d->user_param);
        /* the callback may have destroyed nothing it may not (§5.5.2: GL
        ** calls inside it are undefined); the state is read again */
        ctx->dbg->in_callback = 0;
        return;
    }
    MessageRing *r = d->queue_on && !d->in_callback ? &d->queue : &d->log;
    char *copy = malloc((size_t)length + 1);
    if (!copy)
        return;
    LoggedMessage *m = debug_ring_push(r);
    if (!m) {
        free(copy);
        return;
    }
    memcpy(copy, text, (size_t)length);
    copy[length] = '\0';
    *m = (LoggedMessage){ source, type, id, severity, length + 1, copy };
}

/* one message under the active debug group */
static void debug_emit(GlesContext *ctx, unsigned int source, unsigned int type, unsigned int id,
                       unsigned int severity, const char *text, int length)
{
    debug_emit_in(ctx, ctx->dbg ? ctx->dbg->depth - 1 : 0, source, type, id, severity, text, length);
}

static const char *debug_error_name(unsigned int err)
{
    switch (err) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    case GL_INVALID_FRAMEBUFFER_OPERATION_OES: return "GL_INVALID_FRAMEBUFFER_OPERATION_OES";
    default: return "GL error";
    }
}

static const char *debug_error_reason(unsigned int err)
{
    switch (err) {
    case GL_INVALID_ENUM: return "an enum argument is not one the command accepts";
    case GL_INVALID_VALUE: return "a numeric argument is out of range";
    case GL_INVALID_OPERATION: return "the command is not allowed in the current state";
    case GL_STACK_OVERFLOW: return "the stack is full";
    case GL_STACK_UNDERFLOW: return "the stack is at its bottom";
    case GL_OUT_OF_MEMORY: return "no memory, or past the context's memory budget";
    case GL_INVALID_FRAMEBUFFER_OPERATION_OES: return "the bound framebuffer object is not complete";
    default: return "";
    }
}

/* the command (or family) a core function stands for: gles_TexEnv is
** glTexEnv (glTexEnvf, ...); the helpers that record errors are named by
** the commands that call them */
static void debug_command_name(const char *where, char *out, size_t size)
{
    static const struct { const char *helper, *command; } helpers[] = {
        { "bound_buffer", "a buffer object command" },
        { "set_client_state", "glEnableClientState/glDisableClientState" },
        { "set_pointer", "a gl*Pointer command" },
        { "set_enable", "glEnable/glDisable" },
        { "draw_begin", "a draw command" },
        { "fbo_sync", "a command that draws or reads" },
        { "bound_object", "glBindFramebufferOES/glBindRenderbufferOES" },
        { "gen_names", "glGenFramebuffersOES/glGenRenderbuffersOES" },
        { "compressed_etc1", "glCompressedTexImage2D" },
        { "image_changed", "a texture image command" },
        { "gles_get", "a glGet command" },
        { "gles_GetPointer", "glGetPointerv" },
    };
    out[0] = '\0';
    if (!where)
        return;
    for (size_t i = 0; i < sizeof helpers / sizeof helpers[0]; i++)
        if (strcmp(where, helpers[i].helper) == 0) {
            snprintf(out, size, "%s", helpers[i].command);
            return;
        }
    if (strncmp(where, "gles_", 5) == 0)
        snprintf(out, size, "gl%s", where + 5);
    else
        snprintf(out, size, "%s", where);
}

void debug_error(GlesContext *ctx, unsigned int err, const char *where, const char *why)
{
    /* KHR_debug §2.5: source API, type ERROR, the error's value as its ID,
    ** severity HIGH (Table 5.5: "Any GL error") */
    char command[96], text[DEBUG_MAX_MESSAGE_LENGTH];
    debug_command_name(where, command, sizeof command);
    int n = snprintf(text, sizeof text, "%s%s%s: %s", debug_error_name(err), command[0] ? " in " : "", command,
                     why ? why : debug_error_reason(err));
    if (n < 0)
        return;
    debug_emit(ctx, GL_DEBUG_SOURCE_API_KHR, GL_DEBUG_TYPE_ERROR_KHR, err, GL_DEBUG_SEVERITY_HIGH_KHR, text,
               n < (int)sizeof text ? n : (int)sizeof text - 1);
}

/* the characters of a string argument: `length` when >= 0, else up to its
** terminator; -1 when the string would reach past nbytes (not -1) */
static int64_t debug_string_length(int length, const void *s, int64_t nbytes)
{
    if (length >= 0)
        return nbytes >= 0 && length > nbytes ? -1 : length;
    if (nbytes < 0)
        return (int64_t)strlen(s);
    const void *end = memchr(s, '\0', (size_t)nbytes);
    return end ? (const char *)end - (const char *)s : -1;
}

/* a string argument's length checked against limit (terminator included):
** its characters, -1 with INVALID_VALUE recorded, or -2 with the status
** message set when it reaches past its data (Python-level misuse) */
static int64_t debug_checked_length(GlesContext *ctx, const char *where, const char *what, int length, const void *s,
                                    int64_t nbytes, int limit)
{
    /* the GL rule first: a length given that is past the limit is an
    ** error whatever the data holds */
    if (length >= limit) {
        ctx_error_at(ctx, GL_INVALID_VALUE, where, "the string is not shorter than its maximum length");
        return -1;
    }
    int64_t n = debug_string_length(length, s, nbytes);
    if (n < 0) {
        ctx_message(ctx, GLES_EVALUE, "%s: %s", what, length >= 0 ? "length exceeds the data given"
                                                                    : "no terminator within the data given");
        return -2;
    }
    if (n >= limit) {
        ctx_error_at(ctx, GL_INVALID_VALUE, where, "the string is not shorter than its maximum length");
        return -1;
    }
    return n;
}

/* the length of a message's text (DebugMessageInsert's buf, PushDebugGroup's
** message), which may not be NULL: as debug_checked_length */
static int64_t debug_message_length(GlesContext *ctx, const char *where, const char *what, int length,
                                    const void *text, int64_t nbytes)
{
    if (!text) {
        ctx_error_at(ctx, GL_INVALID_VALUE, where, "the message is NULL");
        return -1;
    }
    return debug_checked_length(ctx, where, what, length, text, nbytes, DEBUG_MAX_MESSAGE_LENGTH);
}

int gles_DebugMessageInsertKHR(GlesContext *ctx, unsigned int source, unsigned int type, unsigned int id,
                               unsigned int severity, int length, const void *buf, int64_t nbytes)
{
    /* §5.5.5: "If the DEBUG_OUTPUT state is disabled calls to
    ** DebugMessageInsert are discarded and do not generate an error" */
    if (!ctx->debug_output)
        return GLES_OK;
    int t = debug_type_index(type);
    if ((source != GL_DEBUG_SOURCE_APPLICATION_KHR && source != GL_DEBUG_SOURCE_THIRD_PARTY_KHR)
        || t < 0 || type == GL_DEBUG_TYPE_PUSH_GROUP_KHR || type == GL_DEBUG_TYPE_POP_GROUP_KHR
        || !debug_severity_bit(severity)) {
        ctx_error_why(ctx, GL_INVALID_ENUM, "source must be APPLICATION or THIRD_PARTY, type one of Table 5.4 "
                                            "but the group types, severity one of Table 5.5");
        return GLES_OK;
    }
    int64_t n = debug_message_length(ctx, __func__, "buf", length, buf, nbytes);
    if (n < 0)
        return n == -2 ? GLES_EVALUE : GLES_OK;
    debug_emit(ctx, source, type, id, severity, buf, (int)n);
    return GLES_OK;
}

void gles_DebugMessageCallbackKHR(GlesContext *ctx, GlesDebugProc callback, const void *user_param)
{
    ctx->dbg->callback = callback;
    ctx->dbg->user_param = user_param;
}

/* up to count messages off ring r into the outputs (any may be NULL), as
** §6.1.15 fetches them: oldest first, stopping at the first whose text
** does not fit what is left of message_log */
static unsigned int debug_fetch(MessageRing *r, unsigned int count, int buf_size, unsigned int *sources,
                                unsigned int *types, unsigned int *ids, unsigned int *severities, int *lengths,
                                char *message_log)
{
    unsigned int got = 0;
    int64_t used = 0;
    while (got < count && r->count > 0) {
        LoggedMessage *m = &r->items[r->start];
        if (message_log) {
            if (m->length > buf_size - used)
                break;
            memcpy(message_log + used, m->text, (size_t)m->length);
            used += m->length;
        }
        if (sources) sources[got] = m->source;
        if (types) types[got] = m->type;
        if (ids) ids[got] = m->id;
        if (severities) severities[got] = m->severity;
        if (lengths) lengths[got] = m->length;
        free(m->text);
        r->start = (r->start + 1) % r->capacity;
        r->count--;
        got++;
    }
    return got;
}

unsigned int gles_GetDebugMessageLogKHR(GlesContext *ctx, unsigned int count, int buf_size, unsigned int *sources,
                                        unsigned int *types, unsigned int *ids, unsigned int *severities,
                                        int *lengths, char *message_log)
{
    /* §6.1.15 (revision 13): "If <bufSize> is less than zero and
    ** <messageLog> is not NULL, an INVALID_VALUE error will be generated" */
    if (buf_size < 0 && message_log) {
        ctx_error_why(ctx, GL_INVALID_VALUE, "bufSize is negative");
        return 0;
    }
    return debug_fetch(&ctx->dbg->log, count, buf_size, sources, types, ids, severities, lengths, message_log);
}

void gles_debug_queue_set(GlesContext *ctx, int on)
{
    ctx->dbg->queue_on = on != 0;
}

int gles_debug_queued(GlesContext *ctx)
{
    const MessageRing *q = &ctx->dbg->queue;
    return q->count ? q->items[q->start].length : 0;
}

unsigned int gles_debug_take(GlesContext *ctx, unsigned int count, int buf_size, unsigned int *sources,
                             unsigned int *types, unsigned int *ids, unsigned int *severities, int *lengths,
                             char *message_log)
{
    return debug_fetch(&ctx->dbg->queue, count, buf_size < 0 ? 0 : buf_size, sources, types, ids, severities,
                       lengths, message_log);
}

/* }==================================================================== */

/* {====================================================================
** debug groups (§5.5.6) */

int gles_PushDebugGroupKHR(GlesContext *ctx, unsigned int source, unsigned int id, int length, const void *message,
                           int64_t nbytes)
{
    DebugState *d = ctx->dbg;
    if (source != GL_DEBUG_SOURCE_APPLICATION_KHR && source != GL_DEBUG_SOURCE_THIRD_PARTY_KHR) {
        ctx_error_why(ctx, GL_INVALID_ENUM, "source must be APPLICATION or THIRD_PARTY");
        return GLES_OK;
    }
    int64_t n = debug_message_length(ctx, __func__, "message", length, message, nbytes);
    if (n < 0)
        return n == -2 ? GLES_EVALUE : GLES_OK;
    if (d->depth == DEBUG_MAX_GROUP_STACK_DEPTH) {
        ctx_error_why(ctx, GL_STACK_OVERFLOW, "the debug group stack is full");
        return GLES_OK;
    }
    MessageGroup *g = &d->groups[d->depth];
    char *copy = malloc((size_t)n + 1);
    if (!copy || !debug_group_copy(g, &d->groups[d->depth - 1])) {
        free(copy);
        ctx_error_why(ctx, GL_OUT_OF_MEMORY, "no memory for the debug group");
        return GLES_OK;
    }
    memcpy(copy, message, (size_t)n);
    copy[n] = '\0';
    g->source = source;
    g->id = id;
    g->message = copy;
    g->length = (int)n + 1;
    d->depth++;
    /* the push's message is raised under the group it leaves (as the pop's
    ** under the one it returns to) */
    debug_emit_in(ctx, d->depth - 2, source, GL_DEBUG_TYPE_PUSH_GROUP_KHR, id, GL_DEBUG_SEVERITY_NOTIFICATION_KHR,
                  g->message, g->length - 1);
    return GLES_OK;
}

void gles_PopDebugGroupKHR(GlesContext *ctx)
{
    DebugState *d = ctx->dbg;
    if (d->depth == 1) {
        ctx_error_why(ctx, GL_STACK_UNDERFLOW, "only the default debug group is on the stack");
        return;
    }
    MessageGroup g = d->groups[--d->depth];
    memset(&d->groups[d->depth], 0, sizeof g);
    debug_emit(ctx, g.source, GL_DEBUG_TYPE_POP_GROUP_KHR, g.id, GL_DEBUG_SEVERITY_NOTIFICATION_KHR, g.message,
               g.length - 1);
    debug_group_clear(&g);
}

/* }==================================================================== */

/* {====================================================================
** labels (§5.5.8) */

/* the namespace of an identifier: DEBUG_NS_*, -1 for the identifiers of
** Table 5.1 whose objects ES 1.1 does not have (no name is one of them:
** INVALID_VALUE), -2 for anything else (INVALID_ENUM) */
static int debug_namespace(unsigned int identifier)
{
    switch (identifier) {
    case GL_BUFFER_KHR: return DEBUG_NS_BUFFER;
    case GL_TEXTURE: return DEBUG_NS_TEXTURE;
    case GL_FRAMEBUFFER_OES: return DEBUG_NS_FRAMEBUFFER;
    case GL_RENDERBUFFER_OES: return DEBUG_NS_RENDERBUFFER;
    case GL_VERTEX_ARRAY_KHR: return DEBUG_NS_VERTEX_ARRAY;
    /* in the ES form's Table 5.1 (it has their KHR tokens), but ES 1.1 has
    ** no shaders, programs, queries or samplers; PROGRAM_PIPELINE_KHR is
    ** removed from the table where pipelines are not supported */
    case GL_SHADER_KHR: case GL_PROGRAM_KHR: case GL_QUERY_KHR: case GL_SAMPLER_KHR: return -1;
    default: return -2;
    }
}

/* whether name is an object of namespace ns: what Is* answers */
static int debug_object_exists(GlesContext *ctx, int ns, unsigned int name)
{
    switch (ns) {
    case DEBUG_NS_BUFFER: return gles_IsBuffer(ctx, name);
    case DEBUG_NS_TEXTURE: return gles_IsTexture(ctx, name);
    case DEBUG_NS_FRAMEBUFFER: return gles_IsFramebufferOES(ctx, name);
    case DEBUG_NS_RENDERBUFFER: return gles_IsRenderbufferOES(ctx, name);
    case DEBUG_NS_VERTEX_ARRAY: return gles_IsVertexArrayOES(ctx, name);
    default: return 0;
    }
}

/* the namespace of a labelled object, or -1 with the GL error recorded
** (naming the command `where`) */
static int debug_label_target(GlesContext *ctx, const char *where, unsigned int identifier, unsigned int name)
{
    int ns = debug_namespace(identifier);
    if (ns == -2) {
        ctx_error_at(ctx, GL_INVALID_ENUM, where, "identifier is not an object namespace of Table 5.1");
        return -1;
    }
    if (ns < 0 || !debug_object_exists(ctx, ns, name)) {
        ctx_error_at(ctx, GL_INVALID_VALUE, where, "name is not an object of the identifier's type");
        return -1;
    }
    return ns;
}

static int debug_label_find(const DebugState *d, uint64_t key)
{
    return debug_lower_bound(d->labels, sizeof *d->labels, d->label_count, key);
}

static void debug_label_remove(DebugState *d, int i)
{
    free(d->labels[i].text);
    memmove(&d->labels[i], &d->labels[i + 1], (size_t)(d->label_count - i - 1) * sizeof *d->labels);
    d->label_count--;
}

void debug_object_deleted(GlesContext *ctx, int ns, unsigned int name)
{
    DebugState *d = ctx->dbg;
    if (!d || !d->label_count)
        return;
    uint64_t key = (uint64_t)ns << 32 | name;
    int i = debug_label_find(d, key);
    if (i < d->label_count && d->labels[i].key == key)
        debug_label_remove(d, i);
}

int gles_ObjectLabelKHR(GlesContext *ctx, unsigned int identifier, unsigned int name, int length, const void *label,
                        int64_t nbytes)
{
    int ns = debug_label_target(ctx, __func__, identifier, name);
    if (ns < 0)
        return GLES_OK;
    int64_t n = 0;
    if (label) {
        n = debug_checked_length(ctx, __func__, "label", length, label, nbytes, DEBUG_MAX_LABEL_LENGTH);
        if (n < 0)
            return n == -2 ? GLES_EVALUE : GLES_OK;
    }
    DebugState *d = ctx->dbg;
    uint64_t key = (uint64_t)ns << 32 | name;
    int i = debug_label_find(d, key);
    int found = i < d->label_count && d->labels[i].key == key;
    if (n == 0) {
        /* NULL removes the label; an empty one is the initial state */
        if (found)
            debug_label_remove(d, i);
        return GLES_OK;
    }
    char *copy = malloc((size_t)n + 1);
    if (!copy) {
        ctx_error_why(ctx, GL_OUT_OF_MEMORY, "no memory for the label");
        return GLES_OK;
    }
    memcpy(copy, label, (size_t)n);
    copy[n] = '\0';
    if (found) {
        free(d->labels[i].text);
    } else {
        if (d->label_count == d->label_capacity) {
            int cap = d->label_capacity ? 2 * d->label_capacity : 16;
            ObjectLabel *l = realloc(d->labels, (size_t)cap * sizeof *l);
            if (!l) {
                free(copy);
                ctx_error_why(ctx, GL_OUT_OF_MEMORY, "no memory for the label");
                return GLES_OK;
            }
            d->labels = l;
            d->label_capacity = cap;
        }
        memmove(&d->labels[i + 1], &d->labels[i], (size_t)(d->label_count - i) * sizeof *d->labels);
        d->label_count++;
        d->labels[i].key = key;
    }
    d->labels[i].text = copy;
    d->labels[i].length = (int)n;
    return GLES_OK;
}

int gles_GetObjectLabelKHR(GlesContext *ctx, unsigned int identifier, unsigned int name, int buf_size, int *length,
                           char *label)
{
    int ns = debug_label_target(ctx, __func__, identifier, name);
    if (ns < 0)
        return 0;
    /* not in KHR_debug's text; OpenGL 4.6 §20.9 makes it INVALID_VALUE */
    if (buf_size < 0) {
        ctx_error_why(ctx, GL_INVALID_VALUE, "bufSize is negative");
        return 0;
    }
    const DebugState *d = ctx->dbg;
    uint64_t key = (uint64_t)ns << 32 | name;
    int i = debug_label_find(d, key);
    const char *text = "";
    int n = 0;
    if (i < d->label_count && d->labels[i].key == key) {
        text = d->labels[i].text;
        n = d->labels[i].length;
    }
    if (!label) {
        /* §6.1.16: no string, the label's length */
        if (length)
            *length = n;
        return 1;
    }
    if (buf_size == 0) {
        if (length)
            *length = 0;
        return 1;
    }
    if (n > buf_size - 1)
        n = buf_size - 1;
    memcpy(label, text, (size_t)n);
    label[n] = '\0';
    if (length)
        *length = n;
    return 1;
}

int gles_ObjectPtrLabelKHR(GlesContext *ctx, int length, const void *label, int64_t nbytes)
{
    /* ES 1.1 has no sync objects: no pointer names one */
    (void)length;
    (void)label;
    (void)nbytes;
    ctx_error_why(ctx, GL_INVALID_VALUE, "ptr is not a sync object (ES 1.1 has none)");
    return GLES_OK;
}

int gles_GetObjectPtrLabelKHR(GlesContext *ctx, int buf_size, int *length, char *label)
{
    (void)buf_size;
    (void)length;
    (void)label;
    ctx_error_why(ctx, GL_INVALID_VALUE, "ptr is not a sync object (ES 1.1 has none)");
    return 0;
}

/* }==================================================================== */
