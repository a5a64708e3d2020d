/* wire.h: the primitive encodings of the trace format (docs/format.md, "Values").
 *
 * Everything is little-endian by definition. Floats travel as their IEEE-754
 * bit patterns through uint32_t/uint64_t, never as host memory. Varints are
 * LEB128 with a hard length limit. The put functions never check space: the
 * caller reserved the worst case (RGL_WMAX_*). The get functions always do.
 */
#ifndef RGL_WIRE_H
#define RGL_WIRE_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

/* Worst-case encoded sizes of each wire type, used to reserve buffer space. */
#define RGL_WMAX_b 1
#define RGL_WMAX_ub 1
#define RGL_WMAX_s 2
#define RGL_WMAX_us 2
#define RGL_WMAX_i 5
#define RGL_WMAX_ui 5
#define RGL_WMAX_f 4
#define RGL_WMAX_d 8
#define RGL_WMAX_e 5
#define RGL_WMAX_bf 5
#define RGL_WMAX_bo 1
#define RGL_WMAX_sz 5
#define RGL_WMAX_h 5
#define RGL_WMAX_ip 10
#define RGL_VARINT32_MAX 5
#define RGL_VARINT64_MAX 10

static inline uint8_t *rgl_put_u8(uint8_t *p, uint8_t v) { *p = v; return p + 1; }

static inline uint8_t *rgl_put_u16(uint8_t *p, uint16_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
    return p + 2;
}

static inline uint8_t *rgl_put_u32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v;
    p[1] = (uint8_t)(v >> 8);
    p[2] = (uint8_t)(v >> 16);
    p[3] = (uint8_t)(v >> 24);
    return p + 4;
}

static inline uint8_t *rgl_put_u64(uint8_t *p, uint64_t v)
{
    p = rgl_put_u32(p, (uint32_t)v);
    return rgl_put_u32(p, (uint32_t)(v >> 32));
}

static inline uint8_t *rgl_put_varint(uint8_t *p, uint64_t v)
{
    while (v >= 0x80) {
        *p++ = (uint8_t)(v | 0x80);
        v >>= 7;
    }
    *p++ = (uint8_t)v;
    return p;
}

static inline uint64_t rgl_zigzag(int64_t v) { return ((uint64_t)v << 1) ^ (uint64_t)(v >> 63); }
static inline int64_t rgl_unzigzag(uint64_t v) { return (int64_t)(v >> 1) ^ -(int64_t)(v & 1); }

static inline uint32_t rgl_f32_bits(float f)
{
    uint32_t u;
    memcpy(&u, &f, 4);
    return u;
}

static inline float rgl_bits_f32(uint32_t u)
{
    float f;
    memcpy(&f, &u, 4);
    return f;
}

static inline uint64_t rgl_f64_bits(double d)
{
    uint64_t u;
    memcpy(&u, &d, 8);
    return u;
}

static inline double rgl_bits_f64(uint64_t u)
{
    double d;
    memcpy(&d, &u, 8);
    return d;
}

/* Typed writers, one per wire type code used in format/commands.def. */
static inline uint8_t *rgl_put_b(uint8_t *p, int8_t v) { return rgl_put_u8(p, (uint8_t)v); }
static inline uint8_t *rgl_put_ub(uint8_t *p, uint8_t v) { return rgl_put_u8(p, v); }
static inline uint8_t *rgl_put_s(uint8_t *p, int16_t v) { return rgl_put_u16(p, (uint16_t)v); }
static inline uint8_t *rgl_put_us(uint8_t *p, uint16_t v) { return rgl_put_u16(p, v); }
static inline uint8_t *rgl_put_i(uint8_t *p, int32_t v) { return rgl_put_varint(p, rgl_zigzag(v)); }
static inline uint8_t *rgl_put_ui(uint8_t *p, uint32_t v) { return rgl_put_varint(p, v); }
static inline uint8_t *rgl_put_f(uint8_t *p, float v) { return rgl_put_u32(p, rgl_f32_bits(v)); }
static inline uint8_t *rgl_put_d(uint8_t *p, double v) { return rgl_put_u64(p, rgl_f64_bits(v)); }
static inline uint8_t *rgl_put_e(uint8_t *p, uint32_t v) { return rgl_put_varint(p, v); }
static inline uint8_t *rgl_put_bf(uint8_t *p, uint32_t v) { return rgl_put_varint(p, v); }
static inline uint8_t *rgl_put_bo(uint8_t *p, uint8_t v) { return rgl_put_u8(p, v); }
static inline uint8_t *rgl_put_sz(uint8_t *p, int32_t v) { return rgl_put_varint(p, rgl_zigzag(v)); }
static inline uint8_t *rgl_put_h(uint8_t *p, uint32_t v) { return rgl_put_varint(p, v); }
static inline uint8_t *rgl_put_ip(uint8_t *p, int64_t v) { return rgl_put_varint(p, rgl_zigzag(v)); }

static inline uint16_t rgl_get_u16(const uint8_t *p) { return (uint16_t)(p[0] | (p[1] << 8)); }

static inline uint32_t rgl_get_u32(const uint8_t *p)
{
    return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}

static inline uint64_t rgl_get_u64(const uint8_t *p)
{
    return (uint64_t)rgl_get_u32(p) | ((uint64_t)rgl_get_u32(p + 4) << 32);
}

/* Reads a varint of at most max_bytes from [*pp, end). Returns 0 on success,
 * -1 when the input ends first, -2 when it is longer than max_bytes or its
 * last byte carries bits beyond 64. Advances *pp only on success. */
static inline int rgl_get_varint(const uint8_t **pp, const uint8_t *end, unsigned max_bytes,
                                 uint64_t *out)
{
    const uint8_t *p = *pp;
    uint64_t v = 0;
    for (unsigned n = 0; n < max_bytes; n++) {
        if (p >= end)
            return -1;
        uint8_t byte = *p++;
        if (n == 9 && byte > 1)
            return -2;
        v |= (uint64_t)(byte & 0x7f) << (7 * n);
        if (!(byte & 0x80)) {
            *pp = p;
            *out = v;
            return 0;
        }
    }
    return -2;
}

#endif
