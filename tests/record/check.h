/* check.h: the small assertion kit of the recorder tests, and helpers that
 * read a trace back through format/'s reader (tracecheck.c).
 *
 * CHECK records a failure and goes on; check_exit() prints the verdict line
 * and returns the exit status for main.
 */
#ifndef RGL_TEST_CHECK_H
#define RGL_TEST_CHECK_H

#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include "format.h"

extern int check_failures, check_passes;

#define CHECK(cond) check_at((cond), __FILE__, __LINE__, #cond, NULL)
#define CHECKM(cond, ...) check_atf((cond), __FILE__, __LINE__, #cond, __VA_ARGS__)

bool check_at(bool ok, const char *file, int line, const char *expr, const char *msg);
#if defined(__GNUC__)
__attribute__((format(printf, 5, 6)))
#endif
bool check_atf(bool ok, const char *file, int line, const char *expr, const char *fmt, ...);

/* Prints "N passed, N failed" and returns the exit status. */
int check_exit(void);

/* A trace read back: every frame and resource decoded into dump lines. */
typedef struct trace_cmds {
    size_t count;
    char **lines;        /* rgl_cmd_format() of each command */
    uint32_t *opcodes;
    bool clean;          /* decoded to the end without error */
} trace_cmds;

/* Decodes a command sequence into lines; the caller frees with
 * trace_cmds_free(). */
trace_cmds trace_cmds_decode(const uint8_t *data, size_t size, uint64_t offset);
void trace_cmds_free(trace_cmds *c);

/* Index of the first line at or after `from` that starts with prefix, or -1. */
long trace_cmds_find(const trace_cmds *c, size_t from, const char *prefix);

/* Count of opcode in the sequence. */
size_t trace_cmds_count(const trace_cmds *c, uint32_t opcode);

/* Prints the lines (for a failing test's log). */
void trace_cmds_print(const trace_cmds *c, const char *title);
/* The end of a decoded trace's checks: c printed under title when any
 * check has failed so far, then freed. */
void trace_cmds_done(trace_cmds *c, const char *title);

/* Opens path with rgl_reader_open_file (CHECKs success). */
rgl_reader *trace_open(const char *path);

/* Frame i of the reader, decoded; *fi receives its info. */
trace_cmds trace_frame(rgl_reader *r, size_t i, rgl_frame_info *fi);

/* Resource id decoded as commands. */
trace_cmds trace_resource_cmds(rgl_reader *r, uint32_t id);

#endif
