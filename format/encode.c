/* encode.c: the encoder, the inverse of decode.c, and the trace builder.
 *
 * rgl_cmd_encode() writes a decoded command back to its bytes (byte-exact:
 * decode then encode gives back the input); the recorder does not use it
 * (its generated entry points write the wire directly) but tools, tests and
 * fuzz seeds do. The header helpers write the fixed layouts both sides
 * share. rgl_trace_builder assembles a whole trace in memory.
 */
#include <float.h>
#include <math.h>
#include <string.h>

#include "format.h"
#include "wire.h"

/* ---- Layout helpers ------------------------------------------------------- */

void rgl_file_header_encode(uint8_t out[RGL_FILE_HEADER_SIZE], uint32_t flags)
{
    uint8_t *p = out;
    memcpy(p, RGL_FILE_MAGIC, RGL_FILE_MAGIC_SIZE);
    p += RGL_FILE_MAGIC_SIZE;
    p = rgl_put_u16(p, RGL_FORMAT_MAJOR);
    p = rgl_put_u16(p, RGL_FORMAT_MINOR);
    p = rgl_put_u32(p, flags);
    p = rgl_put_u32(p, RGL_SAMPLE_U32);
    p = rgl_put_u32(p, RGL_SAMPLE_F32);
    p = rgl_put_u32(p, RGL_FILE_HEADER_SIZE);
    rgl_put_u32(p, rgl_crc32c(0, out, 28));
}

void rgl_chunk_header_encode(uint8_t out[RGL_CHUNK_HEADER_SIZE], uint8_t type, uint32_t size)
{
    uint8_t *p = out;
    memcpy(p, RGL_CHUNK_SYNC, 4);
    p += 4;
    p = rgl_put_u8(p, type);
    p = rgl_put_u8(p, 0);   /* flags */
    p = rgl_put_u16(p, 0);  /* reserved */
    p = rgl_put_u32(p, size);
    rgl_put_u32(p, rgl_crc32c(0, out, 12));
}

/* ---- One command ------------------------------------------------------------- */

rgl_status rgl_cmd_init(rgl_cmd *cmd, uint32_t opcode)
{
    const rgl_cmd_info *info = rgl_cmd_info_get(opcode);
    size_t used = 0;

    memset(cmd, 0, sizeof *cmd);
    if (!info)
        return RGL_E_OPCODE;
    cmd->opcode = opcode;
    cmd->info = info;
    cmd->nargs = info->nargs;
    for (uint32_t i = 0; i < info->nargs; i++) {
        const rgl_arg_desc *d = &info->args[i];
        rgl_arg *a = &cmd->arg[i];
        a->kind = d->kind;
        a->type = d->type;
        switch (d->kind) {
        case RGL_ARG_SCALAR:
            a->count = 1;
            break;
        case RGL_ARG_ARRAY:
            /* Zeroed elements in the scratch space: the command encodes as is. */
            a->count = d->count;
            a->array = cmd->scratch + used;
            used += d->count;
            break;
        case RGL_ARG_COUNTED:
            a->count = 0;
            a->array = cmd->scratch + used;
            used += RGL_ARRAY_MAX;
            break;
        default:
            break;
        }
    }
    return RGL_OK;
}

typedef struct sink {
    uint8_t *p, *end;
    bool bad;
} sink;

static void put_bytes(sink *s, const void *data, size_t n)
{
    if (s->bad || (size_t)(s->end - s->p) < n) {
        s->bad = true;
        return;
    }
    if (n)
        memcpy(s->p, data, n);
    s->p += n;
}

static void put_var(sink *s, uint64_t v)
{
    uint8_t tmp[RGL_VARINT64_MAX];
    put_bytes(s, tmp, (size_t)(rgl_put_varint(tmp, v) - tmp));
}

static void put_fixed(sink *s, uint64_t v, size_t n)
{
    uint8_t tmp[8];
    for (size_t k = 0; k < n; k++)
        tmp[k] = (uint8_t)(v >> (8 * k));
    put_bytes(s, tmp, n);
}

/* A double as float bits; NaN payloads move over by hand (see decode.c). */
static bool double_to_f32_bits(double d, uint32_t *bits)
{
    if (isnan(d)) {
        uint64_t b = rgl_f64_bits(d);
        uint32_t m = (uint32_t)((b >> 29) & 0x007fffffu);
        if (!m)
            m = 0x00400000u; /* payload only in bits a float lacks: quiet NaN */
        *bits = (uint32_t)(b >> 63) << 31 | 0x7f800000u | m;
        return true;
    }
    if (isfinite(d) && fabs(d) > FLT_MAX)
        return false; /* out of range: converting would be undefined */
    *bits = rgl_f32_bits((float)d);
    return true;
}

/* Writes one value of `type`, given as a signed, unsigned or floating value
 * (only the member that matches the type is read). */
static void put_scalar(sink *s, uint8_t type, int64_t i, uint64_t u, double f)
{
    uint32_t bits = 0;
    switch (type) {
    case RGL_T_b:
        if (i < INT8_MIN || i > INT8_MAX) s->bad = true;
        put_fixed(s, (uint8_t)(int8_t)i, 1);
        break;
    case RGL_T_ub:
    case RGL_T_bo:
        if (u > UINT8_MAX) s->bad = true;
        put_fixed(s, u, 1);
        break;
    case RGL_T_s:
        if (i < INT16_MIN || i > INT16_MAX) s->bad = true;
        put_fixed(s, (uint16_t)(int16_t)i, 2);
        break;
    case RGL_T_us:
        if (u > UINT16_MAX) s->bad = true;
        put_fixed(s, u, 2);
        break;
    case RGL_T_i:
    case RGL_T_sz:
        if (i < INT32_MIN || i > INT32_MAX) s->bad = true;
        put_var(s, rgl_zigzag(i));
        break;
    case RGL_T_ip:
        put_var(s, rgl_zigzag(i));
        break;
    case RGL_T_f:
        if (!double_to_f32_bits(f, &bits)) s->bad = true;
        put_fixed(s, bits, 4);
        break;
    case RGL_T_d:
        put_fixed(s, rgl_f64_bits(f), 8);
        break;
    default: /* ui, e, bf, h */
        if (u > UINT32_MAX) s->bad = true;
        put_var(s, u);
        break;
    }
}

/* An array element (a double) as a scalar of `type`: integer types take only
 * integral values in their range. */
static void put_element(sink *s, uint8_t type, double v)
{
    if (type == RGL_T_f || type == RGL_T_d) {
        put_scalar(s, type, 0, 0, v);
        return;
    }
    if (!(v == floor(v)) || v < -2147483648.0 || v > 4294967295.0) {
        s->bad = true;
        return;
    }
    if (v < 0)
        put_scalar(s, type, (int64_t)v, UINT64_MAX, 0); /* negative: bad for unsigned */
    else
        put_scalar(s, type, (int64_t)v, (uint64_t)v, 0);
}

static bool type_signed(uint8_t type)
{
    return type == RGL_T_b || type == RGL_T_s || type == RGL_T_i || type == RGL_T_sz ||
           type == RGL_T_ip;
}

size_t rgl_cmd_encode(const rgl_cmd *cmd, uint8_t *out, size_t cap)
{
    const rgl_cmd_info *info = rgl_cmd_info_get(cmd->opcode);
    sink s = {out, out + cap, false};

    if (!info || cmd->nargs != info->nargs || (cmd->info && cmd->info != info))
        return 0;
    put_var(&s, cmd->opcode);
    for (uint32_t i = 0; i < info->nargs && !s.bad; i++) {
        const rgl_arg_desc *d = &info->args[i];
        const rgl_arg *a = &cmd->arg[i];
        switch (d->kind) {
        case RGL_ARG_SCALAR:
            if (type_signed(d->type))
                put_scalar(&s, d->type, a->v.i, 0, 0);
            else
                put_scalar(&s, d->type, 0, a->v.u, a->v.f);
            break;
        case RGL_ARG_ARRAY:
        case RGL_ARG_COUNTED:
            if (d->kind == RGL_ARG_ARRAY ? a->count != d->count : a->count > RGL_ARRAY_MAX) {
                s.bad = true;
                break;
            }
            if (a->count && !a->array) {
                s.bad = true;
                break;
            }
            if (d->kind == RGL_ARG_COUNTED)
                put_var(&s, a->count);
            for (uint32_t k = 0; k < a->count; k++)
                put_element(&s, d->type, a->array[k]);
            break;
        case RGL_ARG_BLOB:
        case RGL_ARG_STRING:
            if (a->count > (d->kind == RGL_ARG_STRING ? RGL_STRING_MAX : RGL_CHUNK_MAX_PAYLOAD) ||
                (a->count && !a->bytes)) {
                s.bad = true;
                break;
            }
            put_var(&s, a->count);
            put_bytes(&s, a->bytes, a->count);
            break;
        default:
            s.bad = true;
            break;
        }
    }
    return s.bad ? 0 : (size_t)(s.p - out);
}

/* ---- The trace builder --------------------------------------------------------- */

typedef struct chunk_ref {
    uint32_t id; /* resources only */
    uint64_t offset;
} chunk_ref;

struct rgl_trace_builder {
    uint8_t *buf;
    size_t size, cap;
    chunk_ref *frames, *resources;
    size_t nframes, cap_frames, nresources, cap_resources;
    uint32_t next_id;
    rgl_status failed; /* sticky: the first error, or RGL_E_STATE after finish */
};

static rgl_status reserve(rgl_trace_builder *b, size_t extra)
{
    size_t cap = b->cap ? b->cap : 4096;
    uint8_t *nbuf;
    if (extra > SIZE_MAX / 2 - b->size)
        return RGL_E_LIMIT;
    if (b->size + extra <= b->cap)
        return RGL_OK;
    while (cap < b->size + extra)
        cap *= 2;
    nbuf = rgl_format_realloc(b->buf, cap);
    if (!nbuf)
        return RGL_E_NOMEM;
    b->buf = nbuf;
    b->cap = cap;
    return RGL_OK;
}

static rgl_status push_ref(chunk_ref **arr, size_t *n, size_t *cap, uint32_t id, uint64_t offset)
{
    if (*n == *cap) {
        size_t ncap = *cap ? *cap * 2 : 16;
        chunk_ref *na = rgl_format_realloc(*arr, ncap * sizeof *na);
        if (!na)
            return RGL_E_NOMEM;
        *arr = na;
        *cap = ncap;
    }
    (*arr)[*n].id = id;
    (*arr)[*n].offset = offset;
    (*n)++;
    return RGL_OK;
}

/* Appends a chunk whose payload is `head` (varints) then `body`. */
static rgl_status append_chunk(rgl_trace_builder *b, uint8_t type, const uint8_t *head,
                               size_t head_size, const void *body, size_t body_size)
{
    size_t payload = head_size + body_size;
    uint8_t *p;
    rgl_status st;

    if (body_size > RGL_CHUNK_MAX_PAYLOAD || payload > RGL_CHUNK_MAX_PAYLOAD)
        return RGL_E_LIMIT;
    if ((st = reserve(b, RGL_CHUNK_HEADER_SIZE + payload + RGL_CHUNK_TRAILER_SIZE)) != RGL_OK)
        return st;
    p = b->buf + b->size;
    rgl_chunk_header_encode(p, type, (uint32_t)payload);
    if (head_size)
        memcpy(p + RGL_CHUNK_HEADER_SIZE, head, head_size);
    if (body_size)
        memcpy(p + RGL_CHUNK_HEADER_SIZE + head_size, body, body_size);
    rgl_put_u32(p + RGL_CHUNK_HEADER_SIZE + payload,
                rgl_crc32c(0, p + RGL_CHUNK_HEADER_SIZE, payload));
    b->size += RGL_CHUNK_HEADER_SIZE + payload + RGL_CHUNK_TRAILER_SIZE;
    return RGL_OK;
}

static rgl_status builder_fail(rgl_trace_builder *b, rgl_status st)
{
    if (st != RGL_OK && st != RGL_E_ARGUMENT && !b->failed)
        b->failed = st;
    return st;
}

rgl_trace_builder *rgl_trace_builder_create(void)
{
    rgl_trace_builder *b = rgl_format_realloc(NULL, sizeof *b);
    if (!b)
        return NULL;
    memset(b, 0, sizeof *b);
    b->next_id = 1;
    if (reserve(b, RGL_FILE_HEADER_SIZE) != RGL_OK) {
        rgl_format_realloc(b, 0);
        return NULL;
    }
    rgl_file_header_encode(b->buf, 0);
    b->size = RGL_FILE_HEADER_SIZE;
    return b;
}

void rgl_trace_builder_destroy(rgl_trace_builder *b)
{
    if (!b)
        return;
    rgl_format_realloc(b->buf, 0);
    rgl_format_realloc(b->frames, 0);
    rgl_format_realloc(b->resources, 0);
    rgl_format_realloc(b, 0);
}

rgl_status rgl_trace_builder_info(rgl_trace_builder *b, const char *text, size_t size)
{
    if (!b || (size && !text))
        return RGL_E_ARGUMENT;
    if (b->failed)
        return b->failed;
    return builder_fail(b, append_chunk(b, RGL_CHUNK_INFO, NULL, 0, text, size));
}

rgl_status rgl_trace_builder_resource(rgl_trace_builder *b, uint32_t kind, const void *data,
                                      size_t size, uint32_t *id)
{
    uint8_t head[2 * RGL_VARINT32_MAX], *h = head;
    uint64_t offset;
    rgl_status st;

    if (!b || (size && !data))
        return RGL_E_ARGUMENT;
    if (b->failed)
        return b->failed;
    if (b->next_id > RGL_RESOURCE_ID_MAX)
        return builder_fail(b, RGL_E_LIMIT);
    h = rgl_put_varint(h, b->next_id);
    h = rgl_put_varint(h, kind);
    offset = b->size;
    if ((st = append_chunk(b, RGL_CHUNK_RESOURCE, head, (size_t)(h - head), data, size)))
        return builder_fail(b, st);
    if ((st = push_ref(&b->resources, &b->nresources, &b->cap_resources, b->next_id, offset))) {
        b->size = (size_t)offset; /* keep the bytes and the index in step */
        return builder_fail(b, st);
    }
    if (id)
        *id = b->next_id;
    b->next_id++;
    return RGL_OK;
}

rgl_status rgl_trace_builder_frame(rgl_trace_builder *b, uint32_t stream, uint32_t number,
                                   uint32_t flags, uint32_t state, const uint8_t *commands,
                                   size_t size)
{
    uint8_t head[4 * RGL_VARINT32_MAX], *h = head;
    uint64_t offset;
    rgl_status st;

    if (!b || (size && !commands))
        return RGL_E_ARGUMENT;
    if (b->failed)
        return b->failed;
    h = rgl_put_varint(h, stream);
    h = rgl_put_varint(h, number);
    h = rgl_put_varint(h, flags);
    h = rgl_put_varint(h, state);
    offset = b->size;
    if ((st = append_chunk(b, RGL_CHUNK_FRAME, head, (size_t)(h - head), commands, size)))
        return builder_fail(b, st);
    if ((st = push_ref(&b->frames, &b->nframes, &b->cap_frames, 0, offset))) {
        b->size = (size_t)offset;
        return builder_fail(b, st);
    }
    return RGL_OK;
}

rgl_status rgl_trace_builder_finish(rgl_trace_builder *b, bool with_index, const uint8_t **data,
                                    size_t *size)
{
    uint8_t *index = NULL, *p, end[8];
    size_t index_cap;
    uint64_t index_offset;
    rgl_status st = RGL_OK;

    if (!b || !data || !size)
        return RGL_E_ARGUMENT;
    if (b->failed)
        return b->failed;
    if (with_index) {
        index_cap = RGL_VARINT64_MAX * (2 + b->nframes + 2 * b->nresources);
        index = rgl_format_realloc(NULL, index_cap);
        if (!index)
            return builder_fail(b, RGL_E_NOMEM);
        p = rgl_put_varint(index, b->nframes);
        for (size_t i = 0; i < b->nframes; i++)
            p = rgl_put_varint(p, b->frames[i].offset);
        p = rgl_put_varint(p, b->nresources);
        for (size_t i = 0; i < b->nresources; i++) {
            p = rgl_put_varint(p, b->resources[i].id);
            p = rgl_put_varint(p, b->resources[i].offset);
        }
        index_offset = b->size;
        st = append_chunk(b, RGL_CHUNK_INDEX, NULL, 0, index, (size_t)(p - index));
        rgl_format_realloc(index, 0);
        if (st == RGL_OK) {
            rgl_put_u64(end, index_offset);
            st = append_chunk(b, RGL_CHUNK_END, NULL, 0, end, sizeof end);
            if (st != RGL_OK)
                b->size = (size_t)index_offset;
        }
        if (st != RGL_OK)
            return builder_fail(b, st);
    }
    b->failed = RGL_E_STATE;
    *data = b->buf;
    *size = b->size;
    return RGL_OK;
}
