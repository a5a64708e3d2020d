/* decode.c: the command decoder, walking commands.def's descriptors.
 *
 * One command at a time from a borrowed byte range: the opcode, then each
 * argument as its descriptor says. Arrays are converted to double into the
 * command's scratch space; blobs and strings point into the input. Every
 * byte is hostile: each varint, count and length is checked against its
 * hard limit and against the bytes that remain before it is used, nothing
 * is allocated, and an error names the byte offset, the command index and
 * the opcode. Varints must be canonical (no redundant 0x80 continuation
 * groups), so every value has exactly one encoding and decode then encode
 * gives back the input bytes.
 */
#include <math.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "format.h"
#include "wire.h"

enum { CLASS_SIGNED, CLASS_UNSIGNED, CLASS_FLOAT };

static int type_class(uint8_t type)
{
    switch (type) {
    case RGL_T_b: case RGL_T_s: case RGL_T_i: case RGL_T_sz: case RGL_T_ip:
        return CLASS_SIGNED;
    case RGL_T_f: case RGL_T_d:
        return CLASS_FLOAT;
    default:
        return CLASS_UNSIGNED;
    }
}

/* Fewest bytes one element of the type takes: bounds a count against the
 * input before any element is read. */
static size_t type_min_size(uint8_t type)
{
    switch (type) {
    case RGL_T_s: case RGL_T_us: return 2;
    case RGL_T_f: return 4;
    case RGL_T_d: return 8;
    default: return 1;
    }
}

/* A float's bits as a double. NaNs are rebuilt by hand: a conversion
 * instruction would set the quiet bit of a signalling NaN, and the encoder
 * must get the very same bits back. */
static double f32_bits_to_double(uint32_t bits)
{
    if ((bits & 0x7f800000u) == 0x7f800000u && (bits & 0x007fffffu)) {
        uint64_t d = ((uint64_t)(bits >> 31) << 63) | (0x7ffull << 52) |
                     ((uint64_t)(bits & 0x007fffffu) << 29);
        return rgl_bits_f64(d);
    }
    return (double)rgl_bits_f32(bits);
}

/* Reads a varint of at most max_bytes whose value is at most limit.
 * Returns RGL_OK, RGL_E_TRUNCATED or RGL_E_VARINT; advances *pp on success. */
static rgl_status get_var(const uint8_t **pp, const uint8_t *end, unsigned max_bytes,
                          uint64_t limit, uint64_t *out)
{
    const uint8_t *p = *pp;
    uint64_t v;
    int r = rgl_get_varint(&p, end, max_bytes, &v);
    if (r == -1)
        return RGL_E_TRUNCATED;
    if (r != 0)
        return RGL_E_VARINT;
    if ((p - *pp > 1 && p[-1] == 0) || v > limit)
        return RGL_E_VARINT; /* redundant bytes, or too large for the type */
    *pp = p;
    *out = v;
    return RGL_OK;
}

/* Decodes one scalar of `type` into arg->v. */
static rgl_status get_scalar(uint8_t type, const uint8_t **pp, const uint8_t *end, rgl_arg *arg)
{
    const uint8_t *p = *pp;
    size_t left = (size_t)(end - p);
    uint64_t v;
    rgl_status st;

    switch (type) {
    case RGL_T_b:
        if (left < 1) return RGL_E_TRUNCATED;
        arg->v.i = (int8_t)p[0];
        p += 1;
        break;
    case RGL_T_ub:
    case RGL_T_bo:
        if (left < 1) return RGL_E_TRUNCATED;
        arg->v.u = p[0];
        p += 1;
        break;
    case RGL_T_s:
        if (left < 2) return RGL_E_TRUNCATED;
        arg->v.i = (int16_t)rgl_get_u16(p);
        p += 2;
        break;
    case RGL_T_us:
        if (left < 2) return RGL_E_TRUNCATED;
        arg->v.u = rgl_get_u16(p);
        p += 2;
        break;
    case RGL_T_i:
    case RGL_T_sz:
        if ((st = get_var(&p, end, RGL_VARINT32_MAX, UINT32_MAX, &v)) != RGL_OK)
            return st;
        arg->v.i = rgl_unzigzag(v);
        break;
    case RGL_T_ip:
        if ((st = get_var(&p, end, RGL_VARINT64_MAX, UINT64_MAX, &v)) != RGL_OK)
            return st;
        arg->v.i = rgl_unzigzag(v);
        break;
    case RGL_T_f:
        if (left < 4) return RGL_E_TRUNCATED;
        arg->v.f = f32_bits_to_double(rgl_get_u32(p));
        p += 4;
        break;
    case RGL_T_d:
        if (left < 8) return RGL_E_TRUNCATED;
        arg->v.f = rgl_bits_f64(rgl_get_u64(p));
        p += 8;
        break;
    default: /* ui, e, bf, h */
        if ((st = get_var(&p, end, RGL_VARINT32_MAX, UINT32_MAX, &v)) != RGL_OK)
            return st;
        arg->v.u = v;
        break;
    }
    *pp = p;
    return RGL_OK;
}

static double scalar_as_double(const rgl_arg *arg)
{
    switch (type_class(arg->type)) {
    case CLASS_SIGNED: return (double)arg->v.i;
    case CLASS_FLOAT: return arg->v.f;
    default: return (double)arg->v.u;
    }
}

#if defined(__GNUC__)
__attribute__((format(printf, 6, 7)))
#endif
static rgl_status fail(rgl_cmd_iter *it, rgl_status status, const uint8_t *at, uint32_t opcode,
                       const rgl_cmd_info *info, const char *fmt, ...)
{
    rgl_error *e = &it->error;
    size_t used = 0;
    va_list ap;

    e->status = status;
    e->offset = it->base_offset + (uint64_t)(at - it->start);
    e->cmd_index = it->index;
    e->opcode = opcode;
    e->detail[0] = '\0';
    if (info) {
        int n = snprintf(e->detail, sizeof e->detail, "%s: ", info->name);
        used = n > 0 && (size_t)n < sizeof e->detail ? (size_t)n : 0;
    }
    va_start(ap, fmt);
    vsnprintf(e->detail + used, sizeof e->detail - used, fmt, ap);
    va_end(ap);
    return status;
}

void rgl_cmd_iter_init(rgl_cmd_iter *it, const uint8_t *data, size_t size, uint64_t base_offset)
{
    memset(it, 0, sizeof *it);
    it->start = it->pos = data;
    it->end = data ? data + size : data;
    it->base_offset = base_offset;
    it->error.status = RGL_OK;
}

rgl_status rgl_cmd_next(rgl_cmd_iter *it, rgl_cmd *cmd)
{
    const uint8_t *p = it->pos, *end = it->end;
    const rgl_cmd_info *info;
    uint64_t opcode, n;
    size_t used = 0; /* scratch elements taken */
    rgl_status st;

    if (it->error.status != RGL_OK)
        return it->error.status;
    if (p >= end)
        return RGL_END;

    if ((st = get_var(&p, end, RGL_VARINT32_MAX, UINT32_MAX, &opcode)) != RGL_OK)
        return fail(it, st, it->pos, 0, NULL, "bad opcode varint");
    info = opcode < RGL_OPCODE_LIMIT ? rgl_cmd_info_get((uint32_t)opcode) : NULL;
    if (!info)
        return fail(it, RGL_E_OPCODE, it->pos, 0, NULL, "opcode 0x%llx is not in the table",
                    (unsigned long long)opcode);

    cmd->opcode = (uint32_t)opcode;
    cmd->info = info;
    cmd->offset = it->base_offset + (uint64_t)(it->pos - it->start);
    cmd->index = it->index;
    cmd->nargs = info->nargs;

    for (uint32_t i = 0; i < info->nargs; i++) {
        const rgl_arg_desc *d = &info->args[i];
        rgl_arg *a = &cmd->arg[i];
        const uint8_t *at = p;

        a->kind = d->kind;
        a->type = d->type;
        a->v.u = 0;
        a->array = NULL;
        a->bytes = NULL;

        switch (d->kind) {
        case RGL_ARG_SCALAR:
            a->count = 1;
            if ((st = get_scalar(d->type, &p, end, a)) != RGL_OK)
                return fail(it, st, at, info->opcode, info, "arg %u (%s)", i, d->name);
            break;

        case RGL_ARG_ARRAY:
        case RGL_ARG_COUNTED:
            if (d->kind == RGL_ARG_ARRAY) {
                n = d->count;
            } else {
                if ((st = get_var(&p, end, RGL_VARINT32_MAX, UINT32_MAX, &n)) != RGL_OK)
                    return fail(it, st, at, info->opcode, info, "arg %u (%s): bad count", i,
                                d->name);
                if (n > RGL_ARRAY_MAX)
                    return fail(it, RGL_E_LIMIT, at, info->opcode, info,
                                "arg %u (%s): count %llu > %u", i, d->name, (unsigned long long)n,
                                RGL_ARRAY_MAX);
            }
            if (n > (sizeof cmd->scratch / sizeof cmd->scratch[0]) - used)
                return fail(it, RGL_E_LIMIT, at, info->opcode, info,
                            "arg %u (%s): array space exhausted", i, d->name);
            if (n > (size_t)(end - p) / type_min_size(d->type))
                return fail(it, RGL_E_TRUNCATED, at, info->opcode, info,
                            "arg %u (%s): %llu elements do not fit", i, d->name,
                            (unsigned long long)n);
            a->count = (uint32_t)n;
            a->array = cmd->scratch + used;
            for (uint32_t k = 0; k < n; k++) {
                rgl_arg elem = {.type = d->type};
                const uint8_t *eat = p;
                if ((st = get_scalar(d->type, &p, end, &elem)) != RGL_OK)
                    return fail(it, st, eat, info->opcode, info, "arg %u (%s) element %u", i,
                                d->name, k);
                cmd->scratch[used + k] = scalar_as_double(&elem);
            }
            used += (size_t)n;
            break;

        case RGL_ARG_BLOB:
        case RGL_ARG_STRING: {
            uint64_t limit = d->kind == RGL_ARG_STRING ? RGL_STRING_MAX : RGL_CHUNK_MAX_PAYLOAD;
            if ((st = get_var(&p, end, RGL_VARINT32_MAX, UINT32_MAX, &n)) != RGL_OK)
                return fail(it, st, at, info->opcode, info, "arg %u (%s): bad length", i,
                            d->name);
            if (n > limit)
                return fail(it, RGL_E_LIMIT, at, info->opcode, info,
                            "arg %u (%s): length %llu > %llu", i, d->name, (unsigned long long)n,
                            (unsigned long long)limit);
            if (n > (size_t)(end - p))
                return fail(it, RGL_E_TRUNCATED, at, info->opcode, info,
                            "arg %u (%s): %llu bytes do not fit", i, d->name,
                            (unsigned long long)n);
            a->count = (uint32_t)n;
            a->bytes = p;
            p += n;
            break;
        }

        default:
            return fail(it, RGL_E_ARGUMENT, at, info->opcode, info, "bad descriptor");
        }
    }

    it->pos = p;
    it->index++;
    return RGL_OK;
}

uint32_t rgl_cmd_skip_floats(rgl_cmd_iter *it)
{
    const uint8_t *p = it->pos;
    if (it->error.status != RGL_OK || p >= it->end || p[0] >= 0x80)
        return 0;
    size_t n = rgl_cmd_float_size(p[0]);
    if (n == 0 || (size_t)(it->end - p) < n)
        return 0;
    it->pos = p + n;
    it->index++;
    return p[0];
}

/* rgl_cmd_float_size of every one-byte opcode, for the loop below: a byte
 * load per command instead of a call. */
static uint8_t float_sizes[0x80];
static pthread_once_t float_sizes_once = PTHREAD_ONCE_INIT;

static void float_sizes_build(void)
{
    for (uint32_t op = 0; op < 0x80; op++)
        float_sizes[op] = (uint8_t)rgl_cmd_float_size(op); /* 1 + 4 per float: small */
}

size_t rgl_cmd_skip_float_run(rgl_cmd_iter *it)
{
    const uint8_t *p = it->pos, *end = it->end;
    if (it->error.status != RGL_OK)
        return 0;
    pthread_once(&float_sizes_once, float_sizes_build);
    size_t k = 0;
    while (p < end && p[0] < 0x80) {
        size_t n = float_sizes[p[0]];
        if (n == 13 && end - p >= 13) {
            /* Three floats, most calls (glVertex3f, glNormal3f,
             * glColor3f): a branch, which the processor predicts, so the
             * next call's address does not wait for this one's size. */
            p += 13;
            k++;
            continue;
        }
        if (n == 0 || (size_t)(end - p) < n)
            break;
        p += n;
        k++;
    }
    it->pos = p;
    it->index += k;
    return k;
}

static int64_t double_to_i64(double d)
{
    if (isnan(d))
        return 0;
    if (d >= 9223372036854775807.0)
        return INT64_MAX;
    if (d <= -9223372036854775808.0)
        return INT64_MIN;
    return (int64_t)d;
}

double rgl_arg_f(const rgl_arg *arg, uint32_t k)
{
    switch (arg->kind) {
    case RGL_ARG_SCALAR:
        return k == 0 ? scalar_as_double(arg) : 0.0;
    case RGL_ARG_ARRAY:
    case RGL_ARG_COUNTED:
        return arg->array && k < arg->count ? arg->array[k] : 0.0;
    default:
        return arg->bytes && k < arg->count ? (double)arg->bytes[k] : 0.0;
    }
}

int64_t rgl_arg_i(const rgl_arg *arg, uint32_t k)
{
    switch (arg->kind) {
    case RGL_ARG_SCALAR:
        if (k != 0)
            return 0;
        switch (type_class(arg->type)) {
        case CLASS_SIGNED: return arg->v.i;
        case CLASS_FLOAT: return double_to_i64(arg->v.f);
        default: return arg->v.u > (uint64_t)INT64_MAX ? INT64_MAX : (int64_t)arg->v.u;
        }
    case RGL_ARG_ARRAY:
    case RGL_ARG_COUNTED:
        return arg->array && k < arg->count ? double_to_i64(arg->array[k]) : 0;
    default:
        return arg->bytes && k < arg->count ? (int64_t)arg->bytes[k] : 0;
    }
}
