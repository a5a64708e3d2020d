/* tracegen.c: test trace construction (tracegen.h). */
#include "tracegen.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void die(const char *what)
{
    fprintf(stderr, "tracegen: %s\n", what);
    exit(99);
}

void seq_init(seq *s) { memset(s, 0, sizeof *s); }

void seq_free(seq *s)
{
    free(s->data);
    memset(s, 0, sizeof *s);
}

static int is_signed(uint8_t t)
{
    return t == RGL_T_b || t == RGL_T_s || t == RGL_T_i || t == RGL_T_sz || t == RGL_T_ip;
}

void seq_cmd(seq *s, uint32_t opcode, const char *str, const double *v, size_t n)
{
    seq_cmd_bytes(s, opcode, str, str ? strlen(str) : 0, v, n);
}

void seq_cmd_bytes(seq *s, uint32_t opcode, const void *bytes, size_t nbytes, const double *v,
                   size_t n)
{
    const char *str = bytes;
    static rgl_cmd cmd;
    double store[RGL_MAX_ARGS][RGL_ARRAY_MAX];
    size_t used = 0;
    if (rgl_cmd_init(&cmd, opcode) != RGL_OK)
        die("unknown opcode");
    for (uint32_t i = 0; i < cmd.nargs; i++) {
        rgl_arg *a = &cmd.arg[i];
        const rgl_arg_desc *d = &cmd.info->args[i];
        switch (d->kind) {
        case RGL_ARG_SCALAR: {
            double x = used < n ? v[used] : 0;
            used++;
            if (a->type == RGL_T_f || a->type == RGL_T_d)
                a->v.f = x;
            else if (is_signed(a->type))
                a->v.i = (int64_t)x;
            else
                a->v.u = (uint64_t)x;
            break;
        }
        case RGL_ARG_ARRAY:
        case RGL_ARG_COUNTED: {
            size_t cnt = d->kind == RGL_ARG_ARRAY ? d->count : (n > used ? n - used : 0);
            if (cnt > RGL_ARRAY_MAX)
                die("array too long");
            for (size_t k = 0; k < cnt; k++)
                store[i][k] = used + k < n ? v[used + k] : 0;
            used += cnt;
            a->count = (uint32_t)cnt;
            a->array = store[i];
            break;
        }
        case RGL_ARG_STRING:
        case RGL_ARG_BLOB:
            a->bytes = (const uint8_t *)(str ? str : "");
            a->count = (uint32_t)(str ? nbytes : 0);
            break;
        }
    }
    size_t need = 256 + 16 * RGL_ARRAY_MAX * RGL_MAX_ARGS + nbytes;
    if (s->len + need > s->cap) {
        s->cap = (s->len + need) * 2;
        s->data = realloc(s->data, s->cap);
        if (!s->data)
            die("out of memory");
    }
    size_t w = rgl_cmd_encode(&cmd, s->data + s->len, s->cap - s->len);
    if (w == 0)
        die("rgl_cmd_encode failed");
    s->len += w;
}

void seq_framebegin(seq *s, const char *name, const double v[9])
{
    seq_cmd(s, RGL_OP_FrameBegin, name, v, 9);
}

void trace_init(trace *t)
{
    memset(t, 0, sizeof *t);
    t->b = rgl_trace_builder_create();
    if (!t->b)
        die("builder");
}

uint32_t trace_snapshot(trace *t, const seq *s)
{
    uint32_t id;
    if (rgl_trace_builder_resource(t->b, RGL_RES_COMMANDS, s->data, s->len, &id) != RGL_OK)
        die("resource");
    return id;
}

void trace_frame(trace *t, uint32_t stream, uint32_t number, uint32_t flags, uint32_t state,
                 const seq *s)
{
    static const uint8_t none[1];
    if (rgl_trace_builder_frame(t->b, stream, number, flags, state, s->len ? s->data : none,
                                s->len) != RGL_OK)
        die("frame");
}

void trace_finish(trace *t)
{
    if (rgl_trace_builder_finish(t->b, true, &t->data, &t->size) != RGL_OK)
        die("finish");
}

void trace_free(trace *t)
{
    rgl_trace_builder_destroy(t->b);
    memset(t, 0, sizeof *t);
}

void write_file(const char *path, const void *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    if (!f || fwrite(data, 1, size, f) != size || fclose(f) != 0)
        die(path);
}
