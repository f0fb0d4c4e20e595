/*
** debug_output.c -- KHR_debug through the C ABI, as an OpenGL ES 1 program
** uses it: the entry points from eglGetProcAddress (the ES 1 headers name
** the extension only), a debug context from EGL_KHR_create_context, and the
** application's callback called on this thread before each command returns.
** Prints what it checked; exit 0 when every check held, 1 otherwise (the
** harness's 2 and 3 for EGL and GL failures).
*/
#include <string.h>

#include "harness.h"

/* KHR_debug's tokens and types (as GLES2/gl2ext.h spells them) */
#define DEBUG_OUTPUT 0x92E0
#define DEBUG_CALLBACK_FUNCTION 0x8244
#define DEBUG_CALLBACK_USER_PARAM 0x8245
#define DEBUG_SOURCE_API 0x8246
#define DEBUG_SOURCE_APPLICATION 0x824A
#define DEBUG_TYPE_ERROR 0x824C
#define DEBUG_TYPE_MARKER 0x8268
#define DEBUG_TYPE_PUSH_GROUP 0x8269
#define DEBUG_TYPE_POP_GROUP 0x826A
#define DEBUG_SEVERITY_HIGH 0x9146
#define DEBUG_SEVERITY_NOTIFICATION 0x826B
#define DEBUG_LOGGED_MESSAGES 0x9145

typedef void (GL_APIENTRY *DebugProc)(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                                      const char *message, const void *user);
typedef void (GL_APIENTRY *CallbackFn)(DebugProc callback, const void *user);
typedef void (GL_APIENTRY *InsertFn)(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                                     const char *buf);
typedef GLuint (GL_APIENTRY *LogFn)(GLuint count, GLsizei size, GLenum *sources, GLenum *types, GLuint *ids,
                                    GLenum *severities, GLsizei *lengths, char *log);
typedef void (GL_APIENTRY *PushFn)(GLenum source, GLuint id, GLsizei length, const char *message);
typedef void (GL_APIENTRY *PopFn)(void);
typedef void (GL_APIENTRY *LabelFn)(GLenum identifier, GLuint name, GLsizei length, const char *label);
typedef void (GL_APIENTRY *GetLabelFn)(GLenum identifier, GLuint name, GLsizei size, GLsizei *length, char *label);
typedef void (GL_APIENTRY *GetPointervFn)(GLenum pname, void **params);

struct seen {
    int calls;
    GLenum source, type, severity;
    GLuint id;
    char message[1024];
    GLsizei length;
    const void *user;
};

static int failures;

static void check(int ok, const char *what)
{
    printf("%s %s\n", ok ? "ok" : "FAIL", what);
    if (!ok)
        failures++;
}

static void GL_APIENTRY on_message(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length,
                                   const char *message, const void *user)
{
    struct seen *s = (struct seen *)(uintptr_t)user;
    s->calls++;
    s->source = source;
    s->type = type;
    s->id = id;
    s->severity = severity;
    s->length = length;
    s->user = user;
    strncpy(s->message, message, sizeof s->message - 1);
}

#define PROC(type, name) type name = (type)eglGetProcAddress(#name "KHR")

int main(int argc, char **argv)
{
    harness_begin_flags(0, 0, EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR);
    PROC(CallbackFn, glDebugMessageCallback);
    PROC(InsertFn, glDebugMessageInsert);
    PROC(LogFn, glGetDebugMessageLog);
    PROC(PushFn, glPushDebugGroup);
    PROC(PopFn, glPopDebugGroup);
    PROC(LabelFn, glObjectLabel);
    PROC(GetLabelFn, glGetObjectLabel);
    PROC(GetPointervFn, glGetPointerv);
    if (!glDebugMessageCallback || !glDebugMessageInsert || !glGetDebugMessageLog || !glPushDebugGroup
        || !glPopDebugGroup || !glObjectLabel || !glGetObjectLabel || !glGetPointerv) {
        printf("FAIL eglGetProcAddress of the KHR_debug entry points\n");
        return 1;
    }
    check(strstr((const char *)glGetString(GL_EXTENSIONS), "GL_KHR_debug") != NULL, "GL_KHR_debug listed");
    check(glIsEnabled(DEBUG_OUTPUT) == GL_TRUE, "a debug context starts with DEBUG_OUTPUT enabled");

    struct seen seen = {0};
    glDebugMessageCallback(on_message, &seen);
    void *p = NULL;
    glGetPointerv(DEBUG_CALLBACK_FUNCTION, &p);
    check(p == (void *)(uintptr_t)on_message, "DEBUG_CALLBACK_FUNCTION is the callback");
    glGetPointerv(DEBUG_CALLBACK_USER_PARAM, &p);
    check(p == (void *)&seen, "DEBUG_CALLBACK_USER_PARAM is its parameter");

    /* a GL error: the callback has run when the command returns */
    glEnable(0x1234);
    check(seen.calls == 1, "one message for one error, before glEnable returned");
    check(seen.source == DEBUG_SOURCE_API && seen.type == DEBUG_TYPE_ERROR && seen.severity == DEBUG_SEVERITY_HIGH,
          "the error's message is API, ERROR, HIGH");
    check(strstr(seen.message, "glEnable") != NULL, "its text names glEnable");
    check(seen.length == (GLsizei)strlen(seen.message), "its length excludes the terminator");
    check(seen.user == &seen, "the user parameter comes back");
    check(glGetError() == GL_INVALID_ENUM, "the error is recorded too");

    glDebugMessageInsert(DEBUG_SOURCE_APPLICATION, DEBUG_TYPE_MARKER, 42, DEBUG_SEVERITY_NOTIFICATION, 5, "frame0");
    check(seen.calls == 2 && seen.id == 42 && strcmp(seen.message, "frame") == 0 && seen.length == 5,
          "an inserted marker: its id and its first 5 characters");
    if (seen.calls == 2)
        printf("   (id %u, length %d, message \"%s\")\n", seen.id, (int)seen.length, seen.message);
    glPushDebugGroup(DEBUG_SOURCE_APPLICATION, 7, -1, "pass");
    check(seen.calls == 3 && seen.type == DEBUG_TYPE_PUSH_GROUP && seen.id == 7 && strcmp(seen.message, "pass") == 0,
          "the push's message");
    glPopDebugGroup();
    check(seen.calls == 4 && seen.type == DEBUG_TYPE_POP_GROUP && seen.id == 7 && strcmp(seen.message, "pass") == 0,
          "the pop's message repeats the push's");

    /* no callback: messages go to the log */
    glDebugMessageCallback(NULL, NULL);
    glDebugMessageInsert(DEBUG_SOURCE_APPLICATION, DEBUG_TYPE_MARKER, 43, DEBUG_SEVERITY_NOTIFICATION, -1, "logged");
    check(seen.calls == 4, "no callback after it is cleared");
    GLint logged = 0;
    glGetIntegerv(DEBUG_LOGGED_MESSAGES, &logged);
    check(logged == 1, "the message is in the log");
    GLenum source = 0, type = 0, severity = 0;
    GLuint id = 0;
    GLsizei length = 0;
    char text[64] = {0};
    GLuint got = glGetDebugMessageLog(1, sizeof text, &source, &type, &id, &severity, &length, text);
    check(got == 1 && id == 43 && length == 7 && strcmp(text, "logged") == 0, "fetched from the log");

    GLuint tex = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glObjectLabel(GL_TEXTURE, tex, -1, "albedo");
    char label[8] = {0};
    length = -1;
    glGetObjectLabel(GL_TEXTURE, tex, 4, &length, label);
    check(length == 3 && strcmp(label, "alb") == 0, "a texture's label, cut to bufSize - 1");
    glDeleteTextures(1, &tex);
    check(glGetError() == GL_NO_ERROR, "no GL error");

    int status = harness_end(argc, argv);
    return failures ? 1 : status;
}
