/*
** replay_main.c -- the gles-replay program:
**
**     gles-replay TRACE [-o OUT]      (TRACE "-" reads standard input)
**
** plays the trace on the core it is linked with and writes the final colour
** buffer, raw (bottom row first, 4 bytes a pixel for RGBA8888, 2 for
** RGB565, RGBA4444 and RGBA5551), to OUT ("-": standard output). Exit status 0, 1 for a bad trace
** (the reason on standard error), 2 for a usage or I/O error.
**
** Built for an ARM target (__arm__), the frame's begin and end also make a
** system call that no kernel has, number GLES_MARK_SYSCALL: the emulator that
** counts instructions (gles.target) takes its counts there. Under a real
** kernel or qemu the call fails with ENOSYS and changes nothing.
*/
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "replay.h"

#define GLES_MARK_SYSCALL 0x0f1e5

#if defined(__arm__)
static void mark(void *user, int which)
{
    (void)user;
    register long r0 __asm__("r0") = which;
    register long r7 __asm__("r7") = GLES_MARK_SYSCALL;
    __asm__ volatile("svc #0" : "+r"(r0) : "r"(r7) : "memory");
}
#else
static void mark(void *user, int which)
{
    (void)user;
    (void)which;
}
#endif

/* the whole input, 8-byte aligned (malloc's alignment) */
static uint8_t *read_all(int fd, size_t *size)
{
    size_t cap = 1 << 16, n = 0;
    uint8_t *buf = malloc(cap);
    while (buf != NULL) {
        if (n == cap) {
            uint8_t *p = cap > ((size_t)-1) / 2 ? NULL : realloc(buf, cap * 2);
            if (p == NULL) {
                free(buf);
                return NULL;
            }
            buf = p;
            cap *= 2;
        }
        ssize_t got = read(fd, buf + n, cap - n);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0) {
            free(buf);
            return NULL;
        }
        if (got == 0)
            break;
        n += (size_t)got;
    }
    *size = n;
    return buf;
}

static int write_all(int fd, const uint8_t *p, size_t n)
{
    while (n > 0) {
        ssize_t put = write(fd, p, n);
        if (put < 0 && errno == EINTR)
            continue;
        if (put <= 0)
            return -1;
        p += put;
        n -= (size_t)put;
    }
    return 0;
}

int main(int argc, char **argv)
{
    const char *in = NULL, *out = NULL;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "-o") == 0 && i + 1 < argc)
            out = argv[++i];
        else if (in == NULL)
            in = argv[i];
        else
            in = NULL, i = argc;
    }
    if (in == NULL) {
        fprintf(stderr, "usage: gles-replay TRACE [-o OUT]   (TRACE or OUT '-': standard input/output)\n");
        return 2;
    }
    int fd = strcmp(in, "-") == 0 ? 0 : open(in, O_RDONLY);
    if (fd < 0) {
        fprintf(stderr, "gles-replay: %s: %s\n", in, strerror(errno));
        return 2;
    }
    size_t size = 0;
    uint8_t *data = read_all(fd, &size);
    if (fd != 0)
        close(fd);
    if (data == NULL) {
        fprintf(stderr, "gles-replay: %s: could not read the trace\n", in);
        return 2;
    }
    Replay rp;
    memset(&rp, 0, sizeof rp);
    rp.marker = mark;
    if (replay_run(&rp, data, size) != 0) {
        fprintf(stderr, "gles-replay: %s: %s\n", in, rp.error);
        replay_free(&rp);
        free(data);
        return 1;
    }
    int status = 0;
    if (out != NULL) {
        int ofd = strcmp(out, "-") == 0 ? 1 : open(out, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (ofd < 0 || write_all(ofd, gles_color_buffer(rp.ctx), replay_color_bytes(&rp)) != 0) {
            fprintf(stderr, "gles-replay: %s: could not write the image\n", out);
            status = 2;
        }
        if (ofd > 1)
            close(ofd);
    }
    replay_free(&rp);
    free(data);
    return status;
}
