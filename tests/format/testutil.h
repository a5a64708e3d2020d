/* testutil.h: shared helpers of the format tests (header-only).
 *
 * CHECK() counts and reports failures without stopping, so one run shows
 * every failing case; test_summary() prints the tally and gives the exit
 * code. A small deterministic PRNG and a filler that gives any table row
 * arguments valid for their types, extremes included, so a test can build
 * every command there is.
 */
#ifndef RGL_TESTUTIL_H
#define RGL_TESTUTIL_H

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "format.h"
#include "wire.h"

static unsigned long test_checks, test_failures;

#define CHECK(cond) check_((cond), #cond, __FILE__, __LINE__)
#define CHECKF(cond, ...)                                                             \
    (check_((cond), #cond, __FILE__, __LINE__)                                        \
         ? 1                                                                          \
         : (fprintf(stderr, "    "), fprintf(stderr, __VA_ARGS__), fprintf(stderr, "\n"), 0))

static inline int check_(int ok, const char *what, const char *file, int line)
{
    test_checks++;
    if (!ok) {
        test_failures++;
        if (test_failures <= 50)
            fprintf(stderr, "%s:%d: FAILED: %s\n", file, line, what);
    }
    return ok;
}

static inline int test_summary(const char *name)
{
    printf("%s: %lu checks, %lu failed\n", name, test_checks, test_failures);
    return test_failures ? 1 : 0;
}

/* xorshift64*: deterministic across platforms. */
typedef struct rng {
    uint64_t s;
} rng;

static inline uint64_t rng_next(rng *r)
{
    r->s ^= r->s >> 12;
    r->s ^= r->s << 25;
    r->s ^= r->s >> 27;
    return r->s * 0x2545F4914F6CDD1Dull;
}

static inline uint32_t rng_below(rng *r, uint32_t n) { return n ? (uint32_t)(rng_next(r) % n) : 0; }

/* A value for one element of `type`, as the decoder would give it: signed
 * types in i, unsigned in u, floating in f (both set for the array form). */
typedef struct tvalue {
    int64_t i;
    uint64_t u;
    double f;
} tvalue;

static inline double f32_as_double(uint32_t bits)
{
    /* As decode.c: NaN payloads kept bit for bit. */
    if ((bits & 0x7f800000u) == 0x7f800000u && (bits & 0x007fffffu))
        return rgl_bits_f64(((uint64_t)(bits >> 31) << 63) | (0x7ffull << 52) |
                            ((uint64_t)(bits & 0x007fffffu) << 29));
    return (double)rgl_bits_f32(bits);
}

static inline tvalue random_value(rng *r, uint8_t type)
{
    static const int64_t s8[] = {INT8_MIN, INT8_MAX, 0, -1, 1};
    static const int64_t s16[] = {INT16_MIN, INT16_MAX, 0, -1, 1};
    static const int64_t s32[] = {INT32_MIN, INT32_MAX, 0, -1, 1, 63, -64, 64, -65};
    static const int64_t s64[] = {INT64_MIN, INT64_MAX, 0, -1, 1};
    static const uint64_t u32[] = {0, 1, 127, 128, 16383, 16384, UINT32_MAX, 0x4000u};
    static const uint32_t fbits[] = {
        0x00000000u, 0x80000000u, 0x3f800000u, 0xbf800000u, 0x7f800000u, 0xff800000u,
        0x7fc00000u, 0xffc00000u, 0x7fa00001u /* signalling */, 0x7fffffffu,
        0x00000001u /* smallest subnormal */, 0x00800000u, 0x7f7fffffu, 0xff7fffffu,
        0x3dcccccdu /* 0.1f */, 0xc0c00000u};
    static const uint64_t dbits[] = {
        0, 0x8000000000000000ull, 0x3ff0000000000000ull, 0x7ff0000000000000ull,
        0xfff0000000000000ull, 0x7ff8000000000000ull, 0x7ff0000000000001ull,
        0xfff8000000000abcull, 0x0000000000000001ull, 0x7fefffffffffffffull,
        0x3fb999999999999aull /* 0.1 */, 0x0010000000000000ull};
    tvalue v = {0, 0, 0};
    int pick_extreme = rng_below(r, 3) == 0;

    switch (type) {
    case RGL_T_b:
        v.i = pick_extreme ? s8[rng_below(r, 5)] : (int8_t)rng_next(r);
        break;
    case RGL_T_ub:
    case RGL_T_bo:
        v.u = pick_extreme ? (rng_below(r, 2) ? 255 : 0) : (uint8_t)rng_next(r);
        break;
    case RGL_T_s:
        v.i = pick_extreme ? s16[rng_below(r, 5)] : (int16_t)rng_next(r);
        break;
    case RGL_T_us:
        v.u = pick_extreme ? (rng_below(r, 2) ? 65535 : 0) : (uint16_t)rng_next(r);
        break;
    case RGL_T_i:
    case RGL_T_sz:
        v.i = pick_extreme ? s32[rng_below(r, 9)] : (int32_t)(uint32_t)rng_next(r);
        break;
    case RGL_T_ip:
        v.i = pick_extreme ? s64[rng_below(r, 5)] : (int64_t)rng_next(r);
        break;
    case RGL_T_f:
        v.f = f32_as_double(pick_extreme ? fbits[rng_below(r, 16)] : (uint32_t)rng_next(r));
        break;
    case RGL_T_d:
        v.f = rgl_bits_f64(pick_extreme ? dbits[rng_below(r, 12)] : rng_next(r));
        break;
    default: /* ui, e, bf, h */
        v.u = pick_extreme ? u32[rng_below(r, 8)] : (uint32_t)rng_next(r) >> rng_below(r, 32);
        break;
    }
    if (type != RGL_T_f && type != RGL_T_d)
        v.f = (type == RGL_T_b || type == RGL_T_s || type == RGL_T_i || type == RGL_T_sz ||
               type == RGL_T_ip)
                  ? (double)v.i
                  : (double)v.u;
    return v;
}

/* Storage for blob and string bytes of random commands. */
static uint8_t test_bytes[RGL_MAX_ARGS][RGL_STRING_MAX + 64];

/* Sets cmd to `opcode` with random arguments valid for every descriptor. */
static inline void random_cmd(rng *r, rgl_cmd *cmd, uint32_t opcode)
{
    rgl_cmd_init(cmd, opcode);
    for (uint32_t i = 0; i < cmd->nargs; i++) {
        rgl_arg *a = &cmd->arg[i];
        double *arr = (double *)a->array; /* points into cmd->scratch */
        tvalue v;
        uint32_t n;
        switch (a->kind) {
        case RGL_ARG_SCALAR:
            v = random_value(r, a->type);
            if (a->type == RGL_T_f || a->type == RGL_T_d)
                a->v.f = v.f;
            else if (a->type == RGL_T_b || a->type == RGL_T_s || a->type == RGL_T_i ||
                     a->type == RGL_T_sz || a->type == RGL_T_ip)
                a->v.i = v.i;
            else
                a->v.u = v.u;
            break;
        case RGL_ARG_COUNTED:
            n = rng_below(r, 4) == 0 ? (rng_below(r, 2) ? RGL_ARRAY_MAX : 0)
                                     : rng_below(r, RGL_ARRAY_MAX + 1);
            a->count = n;
            /* fall through */
        case RGL_ARG_ARRAY:
            for (uint32_t k = 0; k < a->count; k++)
                arr[k] = random_value(r, a->type).f;
            break;
        case RGL_ARG_BLOB:
        case RGL_ARG_STRING:
            n = a->kind == RGL_ARG_STRING
                    ? (rng_below(r, 4) == 0 ? RGL_STRING_MAX : rng_below(r, 64))
                    : rng_below(r, 300);
            for (uint32_t k = 0; k < n; k++)
                test_bytes[i][k] = (uint8_t)rng_next(r);
            a->count = n;
            a->bytes = test_bytes[i];
            break;
        }
    }
}

/* ---- A small sample trace --------------------------------------------------- */

#define SAMPLE_FRAMES 5
#define SAMPLE_RESOURCES 3

typedef struct sample {
    rgl_trace_builder *builder;
    const uint8_t *data;
    size_t size;
    uint8_t frame_cmds[SAMPLE_FRAMES][512]; /* each frame's command bytes */
    size_t frame_len[SAMPLE_FRAMES];
    uint32_t frame_state[SAMPLE_FRAMES];
    uint8_t res_bytes[SAMPLE_RESOURCES][256];
    size_t res_len[SAMPLE_RESOURCES];
    uint32_t res_id[SAMPLE_RESOURCES];
} sample;

static const char sample_info[] = "program=sample\nrecorder=raygl test\n";

/* Appends command `opcode` with random arguments (short blobs) to buf. */
static inline size_t sample_cmd(rng *r, uint32_t opcode, uint8_t *buf, size_t cap)
{
    static rgl_cmd cmd;
    random_cmd(r, &cmd, opcode);
    for (uint32_t k = 0; k < cmd.nargs; k++) {
        if (cmd.arg[k].kind == RGL_ARG_STRING || cmd.arg[k].kind == RGL_ARG_BLOB)
            cmd.arg[k].count = cmd.arg[k].count > 8 ? 8 : cmd.arg[k].count;
        if (cmd.arg[k].kind == RGL_ARG_COUNTED && cmd.arg[k].count > 4)
            cmd.arg[k].count = 4;
    }
    return rgl_cmd_encode(&cmd, buf, cap);
}

/* Builds INFO, 3 resources (snapshot, texels, list body) and 5 frames on two
 * streams, with or without the index. Returns false on a builder error. */
static inline bool sample_build(sample *s, bool with_index, uint64_t seed)
{
    static const uint32_t ops[] = {RGL_OP_Begin, RGL_OP_Color3f, RGL_OP_Normal3f,
                                   RGL_OP_Vertex3f, RGL_OP_Vertex3f, RGL_OP_Vertex3f,
                                   RGL_OP_End, RGL_OP_Lightfv, RGL_OP_FrameBegin,
                                   RGL_OP_DrawElements, RGL_OP_Matrix, RGL_OP_Sphere};
    rng r = {seed};
    memset(s, 0, sizeof *s);
    s->builder = rgl_trace_builder_create();
    if (!s->builder)
        return false;
    if (rgl_trace_builder_info(s->builder, sample_info, sizeof sample_info - 1) != RGL_OK)
        return false;
    for (int i = 0; i < SAMPLE_RESOURCES; i++) {
        uint32_t kind = i == 1 ? RGL_RES_BYTES : RGL_RES_COMMANDS;
        if (kind == RGL_RES_BYTES) {
            s->res_len[i] = 48;
            for (size_t k = 0; k < 48; k++)
                s->res_bytes[i][k] = (uint8_t)rng_next(&r);
        } else {
            for (int k = 0; k < 4; k++)
                s->res_len[i] += sample_cmd(&r, ops[rng_below(&r, 12)], s->res_bytes[i] + s->res_len[i],
                                            sizeof s->res_bytes[i] - s->res_len[i]);
        }
        if (rgl_trace_builder_resource(s->builder, kind, s->res_bytes[i], s->res_len[i],
                                       &s->res_id[i]) != RGL_OK)
            return false;
    }
    for (int f = 0; f < SAMPLE_FRAMES; f++) {
        for (int k = 0; k < 6; k++)
            s->frame_len[f] += sample_cmd(&r, ops[rng_below(&r, 12)], s->frame_cmds[f] + s->frame_len[f],
                                          sizeof s->frame_cmds[f] - s->frame_len[f]);
        s->frame_state[f] = f % 2 ? 0 : s->res_id[0];
        if (rgl_trace_builder_frame(s->builder, (uint32_t)f % 2, (uint32_t)f / 2,
                                    f % 2 ? RGL_FRAME_STATE_CARRIED : RGL_FRAME_LIVE_CONTEXT,
                                    s->frame_state[f], s->frame_cmds[f], s->frame_len[f]) != RGL_OK)
            return false;
    }
    return rgl_trace_builder_finish(s->builder, with_index, &s->data, &s->size) == RGL_OK;
}

/* Whether frame f of the reader is sample frame f, command bytes and all. */
static inline bool sample_frame_ok(const sample *s, rgl_reader *rd, size_t i, size_t f)
{
    rgl_frame_info fi;
    rgl_error err;
    if (rgl_reader_frame(rd, i, &fi, &err) != RGL_OK)
        return false;
    return fi.stream == f % 2 && fi.number == f / 2 && fi.state == s->frame_state[f] &&
           fi.commands_size == s->frame_len[f] &&
           memcmp(fi.commands, s->frame_cmds[f], s->frame_len[f]) == 0 &&
           fi.flags == (f % 2 ? RGL_FRAME_STATE_CARRIED : RGL_FRAME_LIVE_CONTEXT);
}

/* The chunk layout of a sample trace: offsets of each chunk, in file order. */
typedef struct chunk_span {
    uint64_t start, end;
    uint8_t type;
} chunk_span;

static inline size_t chunk_spans(const uint8_t *d, size_t size, chunk_span *out, size_t cap)
{
    size_t n = 0;
    uint64_t pos = RGL_FILE_HEADER_SIZE;
    while (pos + RGL_CHUNK_HEADER_SIZE <= size && n < cap) {
        uint32_t len = rgl_get_u32(d + pos + 8);
        out[n].start = pos;
        out[n].end = pos + RGL_CHUNK_HEADER_SIZE + len + RGL_CHUNK_TRAILER_SIZE;
        out[n].type = d[pos + 4];
        pos = out[n++].end;
    }
    return n;
}

#endif
