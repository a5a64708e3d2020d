/* tracecheck.c: the assertion kit and the trace read-back helpers of
 * check.h, shared by the recorder tests. */
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

int check_failures, check_passes;

bool check_at(bool ok, const char *file, int line, const char *expr, const char *msg)
{
    if (ok) {
        check_passes++;
        return true;
    }
    check_failures++;
    fprintf(stderr, "%s:%d: check failed: %s%s%s\n", file, line, expr, msg ? ": " : "",
            msg ? msg : "");
    return false;
}

bool check_atf(bool ok, const char *file, int line, const char *expr, const char *fmt, ...)
{
    char msg[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return check_at(ok, file, line, expr, msg);
}

int check_exit(void)
{
    printf("%d passed, %d failed\n", check_passes, check_failures);
    return check_failures ? 1 : 0;
}

trace_cmds trace_cmds_decode(const uint8_t *data, size_t size, uint64_t offset)
{
    trace_cmds c = {0, NULL, NULL, false};
    rgl_cmd_iter it;
    static rgl_cmd cmd;
    size_t cap = 0;
    rgl_cmd_iter_init(&it, data, size, offset);
    for (;;) {
        rgl_status st = rgl_cmd_next(&it, &cmd);
        if (st == RGL_END) {
            c.clean = true;
            break;
        }
        if (st != RGL_OK) {
            fprintf(stderr, "decode error %s at offset %llu (cmd %llu, opcode 0x%x): %s\n",
                    rgl_status_str(st), (unsigned long long)it.error.offset,
                    (unsigned long long)it.error.cmd_index, it.error.opcode, it.error.detail);
            break;
        }
        if (c.count == cap) {
            cap = cap ? 2 * cap : 64;
            c.lines = realloc(c.lines, cap * sizeof *c.lines);
            c.opcodes = realloc(c.opcodes, cap * sizeof *c.opcodes);
        }
        size_t n = rgl_cmd_format(&cmd, NULL, 0);
        c.lines[c.count] = malloc(n + 1);
        rgl_cmd_format(&cmd, c.lines[c.count], n + 1);
        c.opcodes[c.count] = cmd.opcode;
        c.count++;
    }
    return c;
}

void trace_cmds_free(trace_cmds *c)
{
    for (size_t i = 0; i < c->count; i++)
        free(c->lines[i]);
    free(c->lines);
    free(c->opcodes);
    memset(c, 0, sizeof *c);
}

long trace_cmds_find(const trace_cmds *c, size_t from, const char *prefix)
{
    for (size_t i = from; i < c->count; i++)
        if (strncmp(c->lines[i], prefix, strlen(prefix)) == 0)
            return (long)i;
    return -1;
}

size_t trace_cmds_count(const trace_cmds *c, uint32_t opcode)
{
    size_t n = 0;
    for (size_t i = 0; i < c->count; i++)
        n += c->opcodes[i] == opcode;
    return n;
}

void trace_cmds_print(const trace_cmds *c, const char *title)
{
    fprintf(stderr, "--- %s (%zu commands%s)\n", title, c->count, c->clean ? "" : ", damaged");
    for (size_t i = 0; i < c->count; i++)
        fprintf(stderr, "  %s\n", c->lines[i]);
}

void trace_cmds_done(trace_cmds *c, const char *title)
{
    if (check_failures)
        trace_cmds_print(c, title);
    trace_cmds_free(c);
}

rgl_reader *trace_open(const char *path)
{
    rgl_reader *r = NULL;
    rgl_error err;
    rgl_status st = rgl_reader_open_file(path, &r, &err);
    CHECKM(st == RGL_OK, "%s: %s at %llu", path, rgl_status_str(st),
           (unsigned long long)err.offset);
    return r;
}

trace_cmds trace_frame(rgl_reader *r, size_t i, rgl_frame_info *fi)
{
    rgl_error err;
    rgl_status st = rgl_reader_frame(r, i, fi, &err);
    if (!CHECKM(st == RGL_OK, "frame %zu: %s", i, rgl_status_str(st)))
        return (trace_cmds){0, NULL, NULL, false};
    return trace_cmds_decode(fi->commands, fi->commands_size, fi->commands_offset);
}

trace_cmds trace_resource_cmds(rgl_reader *r, uint32_t id)
{
    rgl_resource res;
    rgl_error err;
    rgl_status st = rgl_reader_resource(r, id, &res, &err);
    if (!CHECKM(st == RGL_OK, "resource %u: %s", id, rgl_status_str(st)))
        return (trace_cmds){0, NULL, NULL, false};
    CHECK(res.kind == RGL_RES_COMMANDS);
    return trace_cmds_decode(res.data, res.size, res.data_offset);
}
