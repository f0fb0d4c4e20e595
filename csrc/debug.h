/*
** debug.h -- KHR_debug: debug output (the messages GL errors and the
** application raise, their filters per debug group, the bounded message
** log, the application's callback or the binding's queue) and object labels.
** Owns: DebugState (ctx->dbg) and the DEBUG_OUTPUT enables.
** Never: calls anything but the application's callback, on the calling
**       thread (output is always synchronous).
*/
#ifndef GLES_DEBUG_H
#define GLES_DEBUG_H

#include "state.h"

typedef struct DebugState DebugState;

/* implementation limits (KHR_debug's New Implementation Dependent State,
** each at or above its minimum: 1, 1, 64, 256) */
#define DEBUG_MAX_MESSAGE_LENGTH GLES_DEBUG_MAX_MESSAGE_LENGTH   /* bytes of a message, terminator included */
#define DEBUG_MAX_LOGGED_MESSAGES 64
#define DEBUG_MAX_GROUP_STACK_DEPTH 64  /* the default group included */
#define DEBUG_MAX_LABEL_LENGTH GLES_DEBUG_MAX_LABEL_LENGTH       /* bytes of a label, terminator included */
/* the binding's queue (gles_debug_queue_set) drops messages past this many;
** it is emptied after every command, which raises a few at most */
#define DEBUG_MAX_QUEUED_MESSAGES 4096

/* the state of a new context (DEBUG_OUTPUT off: not a debug context);
** 0 without memory */
int debug_init(GlesContext *ctx);
void debug_free(GlesContext *ctx);
/* DEBUG_OUTPUT_KHR and DEBUG_OUTPUT_SYNCHRONOUS_KHR for Enable, Disable
** and IsEnabled: 1 when cap is one of them (handled), else 0 */
int debug_set_enable(GlesContext *ctx, unsigned int cap, int on);
int debug_is_enabled(const GlesContext *ctx, unsigned int cap, unsigned char *out);
/* the debug state queries (DEBUG_LOGGED_MESSAGES_KHR, ...): count or 0 */
int debug_get(GlesContext *ctx, unsigned int pname, double *out, int *kind);
/* DEBUG_CALLBACK_FUNCTION_KHR, DEBUG_CALLBACK_USER_PARAM_KHR for
** GetPointerv: 1 with *out set when pname is one of them */
int debug_pointer(GlesContext *ctx, unsigned int pname, uintptr_t *out);
/* an object being deleted: its label goes with it */
enum { DEBUG_NS_BUFFER, DEBUG_NS_TEXTURE, DEBUG_NS_FRAMEBUFFER, DEBUG_NS_RENDERBUFFER, DEBUG_NS_VERTEX_ARRAY,
       DEBUG_NS_COUNT };
void debug_object_deleted(GlesContext *ctx, int ns, unsigned int name);

#endif
