/* dump.c: one decoded command as a line of a GL call log.
 *
 *   glLightfv(light=GL_LIGHT0, pname=GL_POSITION, params=[1, 2, 3, 0])
 *
 * Enums print by name (rgl_enum_name) or in hex, handles as #id, blobs as
 * their size, strings quoted and escaped. Floats print with the fewest
 * significant digits that read back to the same value. The text never
 * depends on the locale: printf and strtod both honour LC_NUMERIC, so the
 * shortest precision is searched with the two of them in whatever locale is
 * current (they agree with each other), and the radix character they used
 * is then rewritten to '.'. Digits, sign and exponent are the same in every
 * locale; %g never groups thousands.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "format.h"
#include "wire.h"

typedef struct out {
    char *buf;
    size_t cap, len; /* len counts every byte, written or not */
} out;

static void put(out *o, const char *s, size_t n)
{
    if (o->len < o->cap) {
        size_t room = o->cap - o->len;
        memcpy(o->buf + o->len, s, n < room ? n : room);
    }
    o->len += n;
}

static void puts_(out *o, const char *s) { put(o, s, strlen(s)); }

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void putf(out *o, const char *fmt, ...)
{
    char tmp[64];
    va_list ap;
    int n;
    va_start(ap, fmt);
    n = vsnprintf(tmp, sizeof tmp, fmt, ap);
    va_end(ap);
    if (n > 0)
        put(o, tmp, (size_t)n < sizeof tmp ? (size_t)n : sizeof tmp - 1);
}

/* Copies a %g result, turning whatever radix the locale used (perhaps
 * several bytes) into '.'. */
static void put_number(out *o, const char *s)
{
    char tmp[64];
    size_t n = 0;
    bool radix = false;
    for (; *s && n < sizeof tmp - 1; s++) {
        char c = *s;
        if ((c >= '0' && c <= '9') || c == '-' || c == '+' || c == 'e') {
            tmp[n++] = c;
        } else if (!radix) {
            tmp[n++] = '.';
            radix = true;
        }
    }
    put(o, tmp, n);
}

/* v with `prec` significant digits, as %g would, except that a number
 * below 10^max_exp is written out with its integer digits instead of in
 * exponent form: the significant digits padded with zeros ("100", not
 * "1e+02"; 933313536.0f as "933313540"), which reads back to the same
 * value since the digits are those that already did. */
static const char *shortest_text(char *tmp, size_t cap, double v, int prec, int max_exp)
{
    char digits[24];
    size_t nd = 0;
    const char *p;
    long exp10;

    snprintf(tmp, cap, "%.*e", prec - 1, v);
    for (p = tmp; *p && *p != 'e'; p++)
        if (*p >= '0' && *p <= '9' && nd < sizeof digits)
            digits[nd++] = *p;
    exp10 = *p == 'e' ? strtol(p + 1, NULL, 10) : 0;
    if (exp10 < prec || exp10 >= max_exp || (size_t)exp10 + 2 >= cap) {
        snprintf(tmp, cap, "%.*g", prec, v);
        return tmp;
    }
    size_t n = 0;
    if (v < 0)
        tmp[n++] = '-';
    for (long k = 0; k <= exp10; k++)
        tmp[n++] = (size_t)k < nd ? digits[k] : '0';
    tmp[n] = '\0';
    return tmp;
}

static void put_float(out *o, float v)
{
    char tmp[352]; /* %g bounds: gcc cannot see that prec <= 17 */
    uint32_t bits = rgl_f32_bits(v);
    if (isnan(v)) {
        if ((bits & 0x7fffffffu) == 0x7fc00000u)
            puts_(o, bits >> 31 ? "-nan" : "nan");
        else
            putf(o, "nan(0x%08lx)", (unsigned long)bits);
        return;
    }
    if (isinf(v)) {
        puts_(o, v < 0 ? "-inf" : "inf");
        return;
    }
    /* Reading back is monotonic in the precision (p digits are p+1 digits
     * with a 0 appended), so the fewest digits are found by bisection; 9
     * always suffice for a float. */
    int lo = 1, hi = 9;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        snprintf(tmp, sizeof tmp, "%.*g", mid, (double)v);
        if (strtof(tmp, NULL) == v)
            hi = mid;
        else
            lo = mid + 1;
    }
    put_number(o, shortest_text(tmp, sizeof tmp, (double)v, lo, 9));
}

static void put_double(out *o, double v)
{
    char tmp[352]; /* %g bounds: gcc cannot see that prec <= 17 */
    uint64_t bits = rgl_f64_bits(v);
    if (isnan(v)) {
        if ((bits & 0x7fffffffffffffffull) == 0x7ff8000000000000ull)
            puts_(o, bits >> 63 ? "-nan" : "nan");
        else
            putf(o, "nan(0x%016llx)", (unsigned long long)bits);
        return;
    }
    if (isinf(v)) {
        puts_(o, v < 0 ? "-inf" : "inf");
        return;
    }
    int lo = 1, hi = 17; /* as put_float; 17 digits always suffice */
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        snprintf(tmp, sizeof tmp, "%.*g", mid, v);
        if (strtod(tmp, NULL) == v)
            hi = mid;
        else
            lo = mid + 1;
    }
    put_number(o, shortest_text(tmp, sizeof tmp, v, lo, 15));
}

static void put_enum(out *o, uint64_t v, const char *hint)
{
    const char *name = v <= UINT32_MAX ? rgl_enum_name((uint32_t)v, hint) : NULL;
    if (name)
        puts_(o, name);
    else
        putf(o, "0x%llx", (unsigned long long)v);
}

/* One value of `type`; `f` holds it for f and d, `i`/`u` otherwise. */
static void put_value(out *o, uint8_t type, int64_t i, uint64_t u, double f, const char *hint)
{
    switch (type) {
    case RGL_T_b: case RGL_T_s: case RGL_T_i: case RGL_T_sz: case RGL_T_ip:
        putf(o, "%lld", (long long)i);
        break;
    case RGL_T_f:
        put_float(o, (float)f);
        break;
    case RGL_T_d:
        put_double(o, f);
        break;
    case RGL_T_e:
        put_enum(o, u, hint);
        break;
    case RGL_T_bf:
        putf(o, "0x%llx", (unsigned long long)u);
        break;
    case RGL_T_h:
        putf(o, "#%llu", (unsigned long long)u);
        break;
    case RGL_T_bo:
        if (u <= 1)
            puts_(o, u ? "GL_TRUE" : "GL_FALSE");
        else
            putf(o, "%llu", (unsigned long long)u);
        break;
    default: /* ub, us, ui */
        putf(o, "%llu", (unsigned long long)u);
        break;
    }
}

/* A float argument decoded from the wire is exactly a float; converting it
 * back is exact, and NaNs print from their own bits below. */
static void put_float_arg(out *o, uint8_t type, double v, const char *hint)
{
    if (type == RGL_T_f && isnan(v)) {
        /* Rebuild the float bits as the encoder does, payload included. */
        uint64_t b = rgl_f64_bits(v);
        uint32_t m = (uint32_t)((b >> 29) & 0x007fffffu);
        uint32_t bits = (uint32_t)(b >> 63) << 31 | 0x7f800000u | (m ? m : 0x00400000u);
        put_float(o, rgl_bits_f32(bits));
        return;
    }
    if (type == RGL_T_f && isfinite(v) && fabs(v) > 3.4028234663852886e38) {
        put_double(o, v); /* not a float at all: show it as it is */
        return;
    }
    put_value(o, type, 0, 0, v, hint);
}

static void put_string(out *o, const uint8_t *s, uint32_t n)
{
    static const char hex[] = "0123456789abcdef";
    put(o, "\"", 1);
    for (uint32_t k = 0; k < n; k++) {
        uint8_t c = s[k];
        char esc[4] = {'\\', 0, 0, 0};
        switch (c) {
        case '"': esc[1] = '"'; put(o, esc, 2); break;
        case '\\': esc[1] = '\\'; put(o, esc, 2); break;
        case '\n': esc[1] = 'n'; put(o, esc, 2); break;
        case '\r': esc[1] = 'r'; put(o, esc, 2); break;
        case '\t': esc[1] = 't'; put(o, esc, 2); break;
        default:
            if (c < 0x20 || c >= 0x7f) {
                esc[1] = 'x';
                esc[2] = hex[c >> 4];
                esc[3] = hex[c & 15];
                put(o, esc, 4);
            } else {
                put(o, (const char *)&c, 1);
            }
            break;
        }
    }
    put(o, "\"", 1);
}

size_t rgl_cmd_format(const rgl_cmd *cmd, char *buf, size_t cap)
{
    out o = {buf, cap, 0};
    const rgl_cmd_info *info = cmd->info ? cmd->info : rgl_cmd_info_get(cmd->opcode);

    if (!info) {
        putf(&o, "@unknown_0x%lx()", (unsigned long)cmd->opcode);
    } else {
        uint32_t nargs = cmd->nargs < info->nargs ? cmd->nargs : info->nargs;
        puts_(&o, info->name);
        put(&o, "(", 1);
        for (uint32_t i = 0; i < nargs; i++) {
            const rgl_arg_desc *d = &info->args[i];
            const rgl_arg *a = &cmd->arg[i];
            if (i)
                put(&o, ", ", 2);
            puts_(&o, d->name);
            put(&o, "=", 1);
            switch (d->kind) {
            case RGL_ARG_SCALAR:
                if (d->type == RGL_T_f || d->type == RGL_T_d)
                    put_float_arg(&o, d->type, a->v.f, d->name);
                else
                    put_value(&o, d->type, a->v.i, a->v.u, 0, d->name);
                break;
            case RGL_ARG_ARRAY:
            case RGL_ARG_COUNTED:
                put(&o, "[", 1);
                for (uint32_t k = 0; a->array && k < a->count; k++) {
                    double v = a->array[k];
                    if (k)
                        put(&o, ", ", 2);
                    if (d->type == RGL_T_f || d->type == RGL_T_d)
                        put_float_arg(&o, d->type, v, d->name);
                    else if (isfinite(v) && v == floor(v) && fabs(v) < 9.2e18 &&
                             (v >= 0 || d->type == RGL_T_b || d->type == RGL_T_s ||
                              d->type == RGL_T_i || d->type == RGL_T_sz))
                        put_value(&o, d->type, (int64_t)v, v < 0 ? 0 : (uint64_t)v, 0, d->name);
                    else
                        put_double(&o, v);
                }
                put(&o, "]", 1);
                break;
            case RGL_ARG_BLOB:
                putf(&o, "<%lu bytes>", (unsigned long)a->count);
                break;
            case RGL_ARG_STRING:
                if (a->bytes)
                    put_string(&o, a->bytes, a->count);
                else
                    put(&o, "\"\"", 2);
                break;
            default:
                put(&o, "?", 1);
                break;
            }
        }
        put(&o, ")", 1);
    }
    if (cap)
        buf[o.len < cap ? o.len : cap - 1] = '\0';
    return o.len;
}
